"""Run a parsed console script on a ScriptedMachine; collect the transcript.

The transcript is what the terminal showed: the boot banner, each line's echo
and answer, and for #simh steps the SIMH prompt, command and output; #wait adds
only what the machine printed meanwhile. Line ends are LF. It holds no host
path and no host time, so two runs of a script give the same bytes.
"""
from dataclasses import dataclass, field

from harness.machine.scripted_machine import ScriptError


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
    """Run `steps` in order; stop at the first failure unless keep_going."""
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
