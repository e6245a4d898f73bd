"""The lab bench's full-speed workload (make bench-lab): a FORTH word that runs
a fixed number of instructions, timed from the moment its line is typed to the
` ok`, on build/pdp11 alone (no lab) and in the lab with the page open.

The instruction count comes from the simulator's own clock (SHOW TIME, which
counts instructions; the kernel's WAIT leaps, but the word never waits): two
batch runs typing the same lines, with and without the word's line, each
ending at (BYE)'s HALT; their difference is what the word costs, servo
interrupts included.
"""
import os
import re
import time
from dataclasses import dataclass
from pathlib import Path

from harness.machine import simh
from harness.machine.build import KERNEL, fresh_disk
from harness.machine.console_session import IDLE
from harness.machine.machine import Machine

SETUP = ("1000 LOAD", "Set.Up.Robot", "800 800 400 0 Abs.Move")
DEFINE = ": BENCH.SPIN ( n -- ) 0 DO 10000 0 DO LOOP LOOP ;"
WORK = "3000 BENCH.SPIN"          # 30 million empty LOOPs: a few host seconds
REPEATS = 5                  # rounds, each of the three runs in turn (lab_bench.py)
TICKS_PER_S = os.sysconf("SC_CLK_TCK")
SIM_TIME = re.compile(r"Time:\s+(\d+)")


def cpu_seconds(pid):
    """User + system CPU seconds of one process; None once it has exited."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return None
    return sum(int(f) for f in fields[11:13]) / TICKS_PER_S


@dataclass
class Run:
    """One timed run of WORK: wall seconds, and CPU seconds per process name."""
    wall: float
    cpu: dict

    def share(self, name):
        return self.cpu[name] / self.wall


def timed(pids, work):
    """Run work() (it returns the wall seconds it measured itself, or None for
    the host's); the CPU each of `pids` ({name: [pid, ...]}) used meanwhile."""
    def used():                       # per process: one that exits meanwhile is left out
        return {p: cpu_seconds(p) for group in pids.values() for p in group}
    before, start = used(), time.monotonic()
    wall = work() or time.monotonic() - start
    after = used()
    return Run(wall, {name: sum(after[p] - before[p] for p in group
                                if None not in (before[p], after[p])) for name, group in pids.items()})


def best(runs):
    """The fastest by wall clock (the host's other load only ever slows a run)."""
    return min(runs, key=lambda r: r.wall)


def instructions(tmp):
    """The instructions WORK takes, from two batch runs (see the docstring)."""
    def halted_at(lines):
        keys = "\r".join(SETUP + (DEFINE,) + lines + ("(BYE)",)) + "\r"
        out = simh.run(f"attach rl0 {fresh_disk(tmp, 'bench.dsk')}\nload {KERNEL}\ngo\nshow time\n",
                       keyboard=keys, timeout=600)
        found = SIM_TIME.findall(out)
        if "BENCH.SPIN" not in out or not found:
            raise RuntimeError("the calibration run did not reach (BYE):\n" + out[-500:])
        return int(found[-1])
    return halted_at((WORK,)) - halted_at(())


class Bare:
    """build/pdp11 without the lab (SET CPU IDLE, as `python -m harness console
    --fast` boots it), `extra` SIMH commands before it starts; the set-up typed,
    the word defined. Between its runs it waits at sim>: its idle prompt, paced
    as the harness's machines pace it (SET CLK IDLESPEED=100), took 25 % of a
    core, and the two such machines beside the lab took half a core from the
    lab's run (its simulator got 86-93 % of a core; 100 % without them)."""

    def __init__(self, tmp, name, extra=""):
        self.machine = Machine(disk=fresh_disk(tmp, f"{name}.dsk"), timeout=600,
                               extra_commands=f"{IDLE}\n{extra}")
        for line in SETUP + (DEFINE,):
            self.machine.send(line)
        self.machine.to_sim()

    def run(self, others):
        """WORK typed once; `others` ({name: [pid, ...]}) watched meanwhile."""
        def work():
            self.machine.send(WORK)
        self.machine.cont()                      # outside the timing
        try:
            return timed({"simulator": [self.machine.child.pid], **others}, work)
        finally:
            self.machine.to_sim()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.machine.close()


# Typed into the page as the terminal would send it; the page's clock runs from
# the send to the " ok" written to the terminal.
IN_PAGE = """
const [line, done] = arguments, write = term.write;
let text = "";
term.write = function (data, callback) {
  write.call(term, data, callback);
  text += data;
  if (text.includes(" ok")) { term.write = write; done((performance.now() - start) / 1000); }
};
const start = performance.now();
send({ t: "key", d: line + "\\r" });
"""


def page_run(page, pids):
    """WORK typed into the lab's page once (the word already defined)."""
    page.set_script_timeout(600)
    return timed(pids, lambda: page.execute_async_script(IN_PAGE, WORK))
