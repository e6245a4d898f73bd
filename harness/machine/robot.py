"""The FORTH on build/pdp11 as the robot tests and benchmarks drive it: the
lock-step driving of harness/machine/scripted_machine.py (a stop at QUERY's cue, each
line put into the console receive ring, SIMH STEP for idle time, so every line
starts at an exact instruction count and the same program gives the same
trace), with a FORTH-line interface:

    with Robot(disk=copy_of_robot_dsk, trace="x.csv") as r:
        r.send("1000 LOAD")                 # what the line printed; ForthError on error
        r.send("Set.Up.Robot")
        r.idle(2.0)                         # two simulated seconds pass, FORTH idle
        r.plant()                           # SHOW PLANT, parsed per axis
        r.gripper()                         # its gripper line, parsed
"""
import re

from harness.machine.build import KERNEL, PDP11
from harness.machine.plant_rows import parse_show_gripper, parse_show_plant
from harness.machine.machine import ForthError, MachineHalted
from harness.machine.scripted_machine import ScriptedMachine

def numbers(text):
    """The integers a FORTH line printed."""
    return [int(w) for w in text.split()]


class Robot(ScriptedMachine):
    def __init__(self, disk, trace=None, simulator=PDP11, kernel=KERNEL, timeout=60,
                 sample=None, settings=()):
        """`timeout`: simulated seconds a line may run before it is reported;
        `settings`: SIMH commands before the kernel is loaded (build.CPU_1103)."""
        super().__init__(disk, trace=trace, simulator=simulator, kernel=kernel,
                         line_limit=timeout,
                         settings=[*settings] + ([f"set plant sample={sample}"]
                                                 if sample is not None else []))
        self.banner = self.boot_output

    def _text(self, answer, line=""):
        """The console output of a line: no CRs, no echo, no separating blank."""
        # the DL11 may still be sending the last LF when the breakpoint stops the
        # machine: it then comes out at the start of the next line's output
        out = answer.output.replace("\r", "").lstrip("\n")
        if line and out.startswith(line):
            out = out[len(line):]
        return out[1:] if out.startswith(" ") else out

    def _reply(self, line, answer):
        if answer.stopped:
            raise MachineHalted(f"{line!r}: {answer.stopped}: {answer.output[-300:]!r}")
        out = self._text(answer, line)
        if answer.error:
            return False, out, answer.error
        out = out.rstrip("\n")
        for prompt in (" ok", " compiled"):      # compiled: a definition is open
            if out.endswith(prompt):
                return True, out[:-len(prompt)], ""
        raise MachineHalted(f"no ok after {line!r}: {out!r}")

    def reply(self, line, timeout=None):
        """Give the FORTH one line; (ok, output, error message)."""
        return self._reply(line, self.line(line, timeout))

    def send(self, line, timeout=None):
        ok, out, err = self.reply(line, timeout)
        if not ok:
            raise ForthError(line, err, out)
        return out

    def begin(self, line, seconds):
        """Give the FORTH a line and run only `seconds` of simulated time; the
        output so far (for a line that may never finish: see `finish`)."""
        answer = self.line(line, seconds)
        if not answer.stopped:
            raise MachineHalted(f"the line {line!r} ended within {seconds} s")
        return self._text(answer, line)

    def finish(self, timeout=None):
        """Run on until the FORTH waits for its next line; the output."""
        return self._reply("", self.resume(timeout))[1]

    def idle(self, seconds):
        """Let `seconds` of simulated time pass while the FORTH waits for input."""
        if seconds > 0:
            answer = self.wait(seconds)
            if answer.stopped:
                raise MachineHalted(f"idle {seconds} s: {answer.stopped}")

    def time(self):
        """Simulated seconds since power-up (SHOW CLK)."""
        return float(re.search(r"time=([\d.]+)s", self.simh("show clk")).group(1))

    def plant(self):
        return parse_show_plant(self.simh("show plant"))

    def gripper(self):
        return parse_show_gripper(self.simh("show plant"))

    def examine(self, addr):
        """A memory word (unsigned) read through SIMH."""
        return int(self.simh(f"examine {addr:o}").split(":")[1].split()[0], 8)
