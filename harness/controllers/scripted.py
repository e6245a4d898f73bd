"""A scripted, deterministic run of the five machines (the `controllers run`
command and the regression scenario call it).

run_five(steps, directory, ...) boots the 11/23 and the four 11/03s from copies
of the disk, all members of one lock-step session (coordinator.py), each in a
thread of its own: the 11/03s are typed their boot lines (boot_lines.py) when
the disk holds their blocks and then run free; the 11/23 runs the console
script's steps (script_run.run_steps: the same script language as `run`). When
the 11/23's script is done it QUITs; the coordinator ends the session, the
11/03s stop at that boundary and QUIT. The result: five transcripts (the
console of each, as script_run.Transcript writes them) and the one plant trace.
The same script gives the same bytes, every run.
"""
import re
import tempfile
import threading
from dataclasses import dataclass, field
from pathlib import Path

from harness.blocks.disk import image_block, read_image, write_atomic
from harness.controllers.boot_lines import axis_boot_lines
from harness.controllers.coordinator import CONTROLLERS, MAIN, MEMBERS, Coordinator
from harness.controllers.members import MemberMachine, session_over
from harness.machine.build import KERNEL, KERNEL_1103, PRISTINE_DISK, fresh_disk
from harness.machine import script
from harness.machine.script_run import (Failure, Result, Transcript, check_start_image,
                                        check_writable, run_steps)

FIRST_AXIS_BLOCK = 1080


@dataclass
class FiveResult:
    transcripts: dict = field(default_factory=dict)     # member -> text
    failures: list = field(default_factory=list)        # (member, Failure)
    trace: bytes = b""
    coordinator_said: str = ""


def axis_blocks_present(disk):
    """Does `disk` hold the 11/03's servo (block 1080 not blank)?"""
    return image_block(read_image(disk), FIRST_AXIS_BLOCK).strip(b" \0") != b""


def _axis_part(machine, lines, transcript, failures):
    """Boot lines but the last at the prompt; the last typed as the machine goes free."""
    transcript.console(machine.boot_output)
    for i, line in enumerate(lines[:-1]):
        answer = machine.line(line)
        transcript.console(answer.output)
        if answer.error or answer.stopped:
            failures.append(Failure(i + 1, line, answer.error or answer.stopped))
        if session_over(answer):
            return
        if answer.stopped:
            break
    answer = machine.run_free(lines[-1] if lines else None)
    transcript.console(answer.output)
    if not session_over(answer):
        failures.append(Failure(len(lines), "(free run)", f"stopped: {answer.stopped}"))


class _Member(threading.Thread):
    """One member's thread: boot (its own copy of the disk), then `part(machine)`.
    No thread waits for another: a member stopped at its prompt holds the others
    at the next boundary only until its thread types the next line."""

    def __init__(self, session, member, part):
        super().__init__(name=f"member-{member}")
        self.session, self.member, self.part = session, member, part
        self.machine, self.error = None, None

    def run(self):
        s = self.session
        try:
            copy = fresh_disk(s.directory, f"{self.member}.dsk", source=s.disk)
            self.machine = MemberMachine(
                self.member, s.coordinator.socket, copy.name, s.directory,
                kernel=s.axis_kernel if self.member in CONTROLLERS else s.kernel,
                line_limit=s.line_limit)
            self.part(self.machine)
        except Exception as e:              # reported by the caller; the others released
            self.error = e
            s.coordinator.stop()


@dataclass
class _Setup:
    directory: Path
    disk: Path
    kernel: Path
    axis_kernel: Path
    line_limit: float
    coordinator: Coordinator = None


def run_five(steps, directory, disk=PRISTINE_DISK, keep_going=False, line_limit=60.0,
             kernel=KERNEL, axis_kernel=KERNEL_1103, boot_axes=None, axis_lines=None):
    """Run the 11/23's `steps` (script.Step) with the four 11/03s in `directory`
    (it receives the disks and the trace); the FiveResult. `boot_axes`: type the
    11/03s' boot lines (default: when the disk holds block 1080); `axis_lines`
    (axis name -> lines) types those instead. An error that
    stops a member (its simulator, kernel or disk) is raised once all are down."""
    if boot_axes is None:
        boot_axes = axis_blocks_present(disk)
    setup = _Setup(Path(directory), Path(disk), Path(kernel), Path(axis_kernel), line_limit)
    result, transcripts = FiveResult(), {m: Transcript() for m in MEMBERS}
    axis_failures = {a: [] for a in CONTROLLERS}
    main_result = []

    def main_part(machine):
        main_result.append(run_steps(machine, steps, keep_going=keep_going))
        machine.close()                            # the session ends with the 11/23

    def axis_part(i, a):
        lines = (axis_lines[a] if axis_lines else
                 axis_boot_lines(i) if boot_axes else [])
        return lambda machine: _axis_part(machine, lines, transcripts[a], axis_failures[a])

    with Coordinator(setup.directory, trace="trace.csv") as setup.coordinator:
        threads = [_Member(setup, a, axis_part(i, a)) for i, a in enumerate(CONTROLLERS)]
        threads.append(_Member(setup, MAIN, main_part))
        try:
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            _, result.coordinator_said = setup.coordinator.wait()
        finally:
            for t in threads:
                if t.machine:
                    t.machine.close()
    errors = [(t.member, t.error) for t in threads if t.error]
    if errors:
        member, error = errors[0]
        raise type(error)(f"{member}: {error}") from error
    main = main_result[0]
    result.transcripts[MAIN] = main.transcript
    result.failures = [(MAIN, f) for f in main.failures]
    for a in CONTROLLERS:
        result.transcripts[a] = transcripts[a].text()
        result.failures += [(a, f) for f in axis_failures[a]]
    trace = setup.directory / "trace.csv"
    result.trace = trace.read_bytes() if trace.exists() else b""
    return result


def joined(transcripts):
    """The five transcripts as one text, each under a "===== member" line (the
    regression scenarios' golden: harness/analysis/regression.py)."""
    return "".join(f"===== {m}\n{transcripts[m]}" for m in MEMBERS)


def split_joined(text):
    """joined()'s inverse: member -> transcript."""
    parts = re.split(r"^===== (\w+)\n", text, flags=re.M)[1:]
    return dict(zip(parts[::2], parts[1::2]))


def run_five_file(script_path, transcript_path, trace_path, disk=PRISTINE_DISK,
                  keep_going=False, line_limit=60.0):
    """script_run.run_file's counterpart for the five machines: the 11/23 runs the
    script at script_path; the joined transcripts and the trace are written whole.
    (steps, a Result whose failures name their machine)."""
    steps = script.read(script_path)
    for path in (transcript_path, trace_path):
        check_writable(path)
    check_start_image(Path(disk))
    with tempfile.TemporaryDirectory(prefix="controllers-run-") as tmp:
        five = run_five(steps, tmp, disk=disk, keep_going=keep_going, line_limit=line_limit)
    write_atomic(transcript_path, joined(five.transcripts).encode("latin-1"))
    write_atomic(trace_path, five.trace)
    failures = [f if m == MAIN else Failure(f.lineno, f.text, f"11/03 {m}: {f.message}")
                for m, f in five.failures]
    return steps, Result(joined(five.transcripts), failures, len(steps))
