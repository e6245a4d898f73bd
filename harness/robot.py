"""Drive the FORTH on build/pdp11 in lock-step with simulated time (issue 4).

    with Robot(disk=copy_of_robot_dsk, trace="x.csv") as r:
        r.send("1000 LOAD")                 # output of the line, ForthError on error
        r.send("Set.Up.Robot")
        r.idle(2.0)                         # two simulated seconds pass, FORTH idle
        r.plant()                           # SHOW PLANT, parsed per axis

Why not type into the console as harness/machine.py does: while the FORTH waits
for a line, simulated time runs at the host's pace, so how far an axis drifted
between two commands would depend on the host. Here a SIMH breakpoint on
QUERY stops the simulator whenever the FORTH is about to read a line; the next
line is then put straight into the console's receive ring (the cells the
DL11 interrupt fills: RXHEAD, RXTAIL, RING in forth/kernel/memory.fs) and the
simulator continued. Nothing is typed, nothing can be lost, and every line
starts at an exact instruction count; `idle` lets time pass with SIMH's STEP.
The same program therefore gives the same trace, byte for byte.
"""
import re
from pathlib import Path

import pexpect

from harness.machine import (KERNEL, MACHINE_INI, SIM_PROMPT, SIMULATOR,
                             ForthError, MachineHalted)

ROOT = Path(__file__).resolve().parent.parent
MAP = ROOT / "build" / "kernel.map"
RATE = 300_000                      # instructions per simulated second (CLK RATE)
BREAK = re.compile(r"Breakpoint, PC: (\d+)[^\n]*\n")
STEPPED = re.compile(r"Step expired, PC: (\d+)[^\n]*\n")
AXES = "XYZT"


def numbers(text):
    """The integers a FORTH line printed."""
    return [int(w) for w in text.split()]


def kernel_symbols(path=MAP):
    """name -> address from build/kernel.map ("oooooo name" lines)."""
    table = {}
    for line in Path(path).read_text().splitlines():
        addr, _, name = line.partition(" ")
        table[name] = int(addr, 8)
    return table


def parse_show_plant(text):
    """SHOW PLANT's per-axis rows -> {axis: {pos, vel, dac, vcmd, offset, stop, run, counter}}."""
    axes = {}
    for line in text.splitlines():
        f = line.split()
        if len(f) == 11 and f[0] in AXES and f[3] in ("in", "deg"):
            axes[f[0]] = dict(pos=float(f[1]), vel=float(f[4]), dac=int(f[5]),
                              vcmd=float(f[6]), offset=float(f[7]), stop=f[8],
                              run=int(f[9]), counter=int(f[10]))
    if set(axes) != set(AXES):
        raise ValueError(f"SHOW PLANT output not understood: {text!r}")
    return axes


def ring_commands(line, rxhead, rxtail, ring):
    """SIMH deposits that put a line and its CR into the FORTH's empty console
    receive ring (KEY takes from RXTAIL up to RXHEAD), as if it had been typed."""
    data = line.encode("ascii") + b"\r"
    if len(data) > 128 or b"\n" in data:
        raise ValueError("one line of at most 127 characters")
    padded = data + b"\0" * (len(data) & 1)
    commands = [f"deposit {rxtail:o} 0"]
    for k in range(0, len(padded), 2):
        commands.append(f"deposit {ring + k:o} {padded[k] | padded[k + 1] << 8:o}")
    return commands + [f"deposit {rxhead:o} {len(data):o}"]


class Robot:
    def __init__(self, disk, trace=None, simulator=SIMULATOR, kernel=KERNEL,
                 timeout=60, sample=None):
        sym = kernel_symbols()
        self.query = sym["QUERY"]
        self.rxhead, self.rxtail, self.ring = sym["RXHEAD"], sym["RXTAIL"], sym["RING"]
        self.timeout = timeout
        self.child = pexpect.spawn(str(simulator), cwd=str(ROOT), encoding="latin-1",
                                   timeout=timeout, dimensions=(24, 200))
        self.child.delaybeforesend = None
        self.child.expect(SIM_PROMPT)
        self._sim(f"do {MACHINE_INI}")
        if sample is not None:
            self._sim(f"set plant sample={sample}")
        if trace:
            self._sim(f"attach plant {trace}")
        self._sim(f"attach rl0 {disk}")
        self._sim(f"load {kernel}")
        self._sim(f"break {self.query:o}")
        self.banner = self._run("go")

    # ---- the simulator's command line ----------------------------------------------
    def _sim(self, command, timeout=10):
        """One SIMH command at the sim> prompt; what it printed."""
        self.child.sendline(command)
        i = self.child.expect([SIM_PROMPT, pexpect.EOF, pexpect.TIMEOUT], timeout=timeout)
        if i:
            raise MachineHalted(f"SIMH did not come back after {command!r}")
        out = self.child.before
        return out[len(command):].lstrip("\r\n") if out.startswith(command) else out

    def _run(self, command, timeout=None):
        """Continue the machine until the FORTH next waits for a line; its output."""
        out = self._sim(command, timeout or self.timeout)
        m = BREAK.search(out)
        if not m or int(m.group(1), 8) != self.query:
            raise MachineHalted(f"the machine stopped elsewhere: {out[-500:]!r}")
        return out[:m.start()]

    # ---- FORTH lines -------------------------------------------------------------------
    def _put(self, line):
        """The line and its CR into the console's receive ring, as if typed."""
        for command in ring_commands(line, self.rxhead, self.rxtail, self.ring):
            self._sim(command)

    def reply(self, line, timeout=None):
        """Give the FORTH one line; (ok, output, error message)."""
        self._put(line)
        # the DL11 may still be sending the last LF when the breakpoint stops the
        # machine: it then comes out at the start of the next line's output
        out = self.finish(timeout).lstrip("\n")
        if out.startswith(line):
            out = out[len(line):]
        out = out[1:] if out.startswith(" ") else out
        err = re.search(r"\nError: ([^\n]*)\n", out)
        if err:
            return False, out, err.group(1)
        out = out.rstrip("\n")
        if not out.endswith(" ok"):
            raise MachineHalted(f"no ok after {line!r}: {out!r}")
        return True, out[:-3], ""

    def begin(self, line, seconds):
        """Give the FORTH a line and run only `seconds` of simulated time; the
        output so far (for a line that may never finish: see `finish`)."""
        self._put(line)
        out = self._sim(f"step {round(seconds * RATE)}", timeout=self.timeout)
        if not STEPPED.search(out):
            raise MachineHalted(f"the line {line!r} ended within {seconds} s: {out!r}")
        return out[:STEPPED.search(out).start()].replace("\r", "")

    def finish(self, timeout=None):
        """Run on until the FORTH waits for its next line; the output."""
        return self._run("cont", timeout).replace("\r", "")

    def send(self, line, timeout=None):
        ok, out, err = self.reply(line, timeout)
        if not ok:
            raise ForthError(line, err, out)
        return out

    # ---- time and the plant ----------------------------------------------------------
    def idle(self, seconds):
        """Let `seconds` of simulated time pass while the FORTH waits for input."""
        n = round(seconds * RATE)
        if n > 0:
            out = self._sim(f"step {n}", timeout=self.timeout)
            if not STEPPED.search(out):
                raise MachineHalted(f"step {n} ended early: {out[-300:]!r}")

    def time(self):
        """Simulated seconds since power-up (SHOW CLK)."""
        return float(re.search(r"time=([\d.]+)s", self._sim("show clk")).group(1))

    def plant(self):
        return parse_show_plant(self._sim("show plant"))

    def examine(self, addr):
        """A memory word (unsigned) read through SIMH."""
        out = self._sim(f"examine {addr:o}")
        return int(out.split(":")[1].split()[0], 8)

    def close(self):
        if self.child.isalive():
            try:
                self.child.sendline("quit")
                self.child.expect(pexpect.EOF, timeout=5)
            except (pexpect.TIMEOUT, OSError):
                pass
            self.child.close(force=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
