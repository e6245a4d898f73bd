"""Run a parsed console script on a ScriptedMachine; collect the transcript.

The transcript is what the terminal showed: the boot banner, each line's echo
and answer, and for #simh steps the SIMH prompt, command and output; #wait adds
only what the machine printed meanwhile. Line ends are LF. It holds no host
path and no host time, so two runs of a script give the same bytes.

run_file() is the whole of a scripted run (the `run` command and the regression
scenarios call it): a fresh copy of the disk, the machine, the steps, the
transcript and the plant trace written whole.
"""
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from harness.blocks.disk import DiskError, check_image, check_not_held, write_atomic
from harness.machine import script
from harness.machine.build import KERNEL, PDP11, PRISTINE_DISK, fresh_disk
from harness.machine.scripted_machine import ScriptError, ScriptedMachine
from harness.machine.simh import SimhError

STEP_KINDS = ("forth", "wait", "simh")      # script.Step.kind
# what a run reports as the user's error (a bad script, disk, kernel or machine)
ERRORS = (script.ScriptSyntaxError, ScriptError, SimhError, DiskError)


class Transcript:
    """Console output as it arrives, with SIMH exchanges put in between.

    The console's transmitter may still hold the LF of a CR LF when the machine
    stops; it arrives at the start of the next console output. A SIMH exchange
    put in between ends that line itself and drops the late LF."""

    def __init__(self):
        self._parts = []
        self._late_lf = False

    def console(self, text):
        if self._late_lf and text.startswith("\n"):
            text = text[1:]
        self._late_lf = False
        self._parts.append(text)

    def simh(self, command, output):
        if self._parts and self._parts[-1].endswith("\r"):
            self._parts.append("\n")
            self._late_lf = True
        self._parts.append(f"sim> {command}\r\n{output}")

    def text(self):
        text = "".join(self._parts).replace("\r\n", "\n")
        return text[:-1] + "\n" if text.endswith("\r") else text


@dataclass
class Failure:
    lineno: int
    text: str        # the script line or directive
    message: str     # what went wrong

    def where(self, name):
        return f"{name}:{self.lineno}: {self.message} (in: {self.text})"


@dataclass
class Result:
    transcript: str
    failures: list = field(default_factory=list)
    steps_run: int = 0


def _failure(answer):
    """What went wrong with a line ("" if nothing). A stop comes first: a line that
    printed an error and then ran on is reported as having hit the line limit."""
    if answer.stopped:
        printed = f"; it had printed Error: {answer.error}" if answer.error else ""
        return f"the simulator stopped: {answer.stopped}{printed}"
    if answer.error:
        return f"Error: {answer.error}"
    return ""


def run_steps(machine, steps, keep_going=False):
    """Run `steps` in order; stop at the first failure unless keep_going. A step
    of a kind the runner does not know is refused (ScriptError) before any runs."""
    unknown = [s for s in steps if s.kind not in STEP_KINDS]
    if unknown:
        raise ScriptError(f"line {unknown[0].lineno}: a step of kind {unknown[0].kind!r}; "
                          f"a script's steps are {', '.join(STEP_KINDS)}")
    transcript = Transcript()
    transcript.console(machine.boot_output)
    result = Result("")
    for step in steps:
        result.steps_run += 1
        if step.kind == "simh":
            try:
                transcript.simh(step.text, machine.simh(step.text))
                continue
            except ScriptError as e:      # SIMH refused the command; the machine is fine
                transcript.simh(step.text, e.output)
                result.failures.append(Failure(step.lineno, step.text, str(e)))
                if keep_going:
                    continue
                break
        answer = machine.wait(step.seconds) if step.kind == "wait" else machine.line(step.text)
        transcript.console(answer.output)
        if machine.left_with_bye(answer):       # BYE ends the session, as at the console
            later = len(steps) - result.steps_run
            if later:
                result.failures.append(Failure(step.lineno, step.text,
                                               f"BYE ended the session; {later} later steps not run"))
            break
        message = _failure(answer)
        if not message:
            continue
        if keep_going and answer.running:        # stop the runaway line as a user would
            stopped = machine.interrupt()
            transcript.console(stopped.output)
            message += ("; ^C typed, the run goes on" if not stopped.stopped else
                        f"; ^C typed, and still {stopped.stopped}")
            answer = stopped
        result.failures.append(Failure(step.lineno, step.text, message))
        if answer.stopped or not keep_going:     # a stopped machine cannot go on
            break
    result.transcript = transcript.text()
    return result


def check_writable(path):
    parent = path.parent
    if not parent.is_dir():
        raise ScriptError(f"{parent}: no such directory for {path.name} (output "
                          "directories must exist, as for plot)")
    if path.is_dir():
        raise ScriptError(f"{path}: is a directory, not a file to write")


def check_start_image(disk):
    """The image a run starts from is only read (each run boots a copy): it must be
    there, readable and RL02-sized (harness.blocks.disk.check_image), and no other
    simulator may be writing it; DiskError if not."""
    if disk == PRISTINE_DISK and not disk.exists():
        raise DiskError(f"{disk}: no such disk image (run make)")
    check_image(disk, writable=False)
    check_not_held(disk, "a scripted run copies the image, and a simulator writing it "
                   "could change it half-way: leave that one first")


def run_file(script_path, transcript_path, trace_path, disk=PRISTINE_DISK,
             keep_going=False, line_limit=60.0, kernel=KERNEL, simulator=PDP11, settings=()):
    """Run the console script at script_path on a fresh copy of `disk`; write the
    transcript and the plant trace (whole, even when a line failed). (steps,
    Result); one of ERRORS, with nothing written, if the run cannot start.
    `settings`: SIMH commands before the run (ScriptedMachine's, e.g. SET CLK TIMED)."""
    steps = script.read(script_path)
    for path in (transcript_path, trace_path):
        check_writable(path)
    disk, kernel = Path(disk), Path(kernel)
    check_start_image(disk)
    with tempfile.TemporaryDirectory(prefix="harness-run-") as tmp:
        try:
            copy = fresh_disk(tmp, source=disk)
        except OSError as e:
            raise ScriptError(f"{disk}: cannot copy the disk image: {e.strerror}") from e
        check_image(copy)                        # the copy the machine changes
        with ScriptedMachine(copy.name, trace="trace.csv", cwd=tmp, simulator=simulator,
                             line_limit=line_limit, kernel=kernel,
                             kernel_map=kernel.with_suffix(".map"), settings=settings) as m:
            result = run_steps(m, steps, keep_going=keep_going)
        trace = (Path(tmp) / "trace.csv").read_bytes()
    write_atomic(transcript_path, result.transcript.encode("latin-1"))
    write_atomic(trace_path, trace)
    return steps, result
