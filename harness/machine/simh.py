"""Run a SIMH script through build/pdp11 and give back what it printed.

The small, shared way for test code and tools to drive the simulator in batch:

    from harness.machine import simh
    out = simh.run(simh.deposit(0o1000, [0o012700, 0o001234, 0]) + "go 1000\\nexamine r0\\n")
    simh.examined(out)["R0"]          # -> 0o1234

run(script, machine=True, simulator=PDP11, timeout=120, cwd=None, keyboard="") -> str
    Writes `script` to a temporary file and runs the simulator on it. With
    machine=True the script starts with `do pdp11-devices/machine.ini` (the
    shared machine configuration); `quit` is always appended, so the
    simulator never waits at its prompt. `keyboard` (text) is what the
    console keyboard (DL11 TTI) receives, all of it available from the
    start; the script itself is read from its file. Returns stdout and
    stderr together, as the simulator printed them. Raises SimhError if the
    simulator is missing, exits non-zero or outlives `timeout` (wall seconds:
    a guard only; simulated time never depends on it). A program that never
    halts needs `step N` (N instructions) rather than `go`.
stream(script, ...) -> context manager yielding an iterator of output lines
    The same as run(), for output too large to hold in memory.
deposit(address, words) -> str
    Script lines depositing `words` (ints) at consecutive even addresses.
examined(output, radix=8) -> dict
    Every "NAME:<tab>number" line (SIMH's EXAMINE output) as name -> int,
    read in `radix` (8 for memory and most registers; 10 for registers SIMH
    shows in decimal, such as CLK TICKS); a name examined twice keeps its
    last value. Memory addresses appear as their octal text ("2000").
examined_all(output, radix=8) -> list of (name, int)
    The same, in order, keeping repeats.
"""
import contextlib
import re
import subprocess
import tempfile
import threading
from pathlib import Path

from harness.machine.build import KERNEL, MACHINE_INI, PDP11

_EXAMINED = re.compile(r"^([A-Za-z0-9_]+):\t([0-9]+)\s*$", re.M)


# The simulator's exit status when the startup script's disk is written by another
# simulator (pdp11-devices/simh/rl_one_writer.c), and after QUIT -F left UPDATEd blocks
# unwritten (pdp11-devices/simh/leave_check.c).
DISK_HELD = 3
LEFT_WITHOUT_BLOCKS = 1


def boot_script(disk, kernel=KERNEL, setup="", read_only=False):
    """SIMH commands that boot the FORTH: the machine, the disk (read_only:
    ATTACH -R, beside a simulator that writes it), `setup` (more SIMH command
    lines, each ending in a newline), the kernel, start."""
    return (f"do {MACHINE_INI}\n"
            f"attach {'-r ' if read_only else ''}rl0 {Path(disk).resolve()}\n"
            f"{setup}"
            f"load {kernel}\n"
            "go\n")


class SimhError(RuntimeError):
    """The simulator could not be run, failed, or did not finish in time."""


@contextlib.contextmanager
def _script_files(script, machine, keyboard):
    """A temporary directory holding the script (machine.ini first, `quit`
    last) and the keyboard file; yields their paths."""
    text = (f"do {MACHINE_INI}\n" if machine else "") + script
    if not text.endswith("\n"):
        text += "\n"
    text += "quit\n"
    with tempfile.TemporaryDirectory() as tmp:
        path, keys = Path(tmp) / "script.ini", Path(tmp) / "keyboard"
        path.write_text(text)
        keys.write_text(keyboard)           # a file, not a pipe: no race with the writer
        yield path, keys


def _check_simulator(simulator):
    simulator = Path(simulator)
    if not simulator.exists():
        raise SimhError(f"{simulator} does not exist: run make first")
    return simulator


def run(script, machine=True, simulator=PDP11, timeout=120, cwd=None, keyboard=""):
    simulator = _check_simulator(simulator)
    with _script_files(script, machine, keyboard) as (path, keys):
        try:
            with open(keys) as stdin:
                proc = subprocess.run([str(simulator), str(path)], stdin=stdin,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                      text=True, timeout=timeout, cwd=cwd)
        except subprocess.TimeoutExpired as e:
            raise SimhError(f"{simulator.name} did not finish within {timeout} s") from e
    if proc.returncode != 0:
        raise SimhError(f"{simulator.name} exited with {proc.returncode}:\n{proc.stdout}")
    return proc.stdout


@contextlib.contextmanager
def stream(script, machine=True, simulator=PDP11, timeout=600, cwd=None, keyboard=""):
    """Like run(), but yields an iterator over the output's lines as the
    simulator prints them, for output too large to hold (CPU history)."""
    simulator = _check_simulator(simulator)
    with _script_files(script, machine, keyboard) as (path, keys), open(keys) as stdin:
        proc = subprocess.Popen([str(simulator), str(path)], stdin=stdin,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, cwd=cwd)
        timer = threading.Timer(timeout, proc.kill)   # a guard, as in run()
        timer.start()
        try:
            yield proc.stdout
            for _ in proc.stdout:                     # the rest, unread by the caller
                pass
            status = proc.wait()
        except BaseException:
            proc.kill()                               # the caller gave up: stop it
            proc.wait()
            raise
        finally:
            timer.cancel()
            proc.stdout.close()
        if timer.finished.is_set() and status < 0:
            raise SimhError(f"{simulator.name} did not finish within {timeout} s")
        if status != 0:
            raise SimhError(f"{simulator.name} exited with {status}")


def deposit(address, words):
    return "".join(f"deposit {address + 2 * i:o} {w & 0o177777:06o}\n"
                   for i, w in enumerate(words))


def examined_all(output, radix=8):
    found = []
    for m in _EXAMINED.finditer(output):
        try:
            found.append((m.group(1), int(m.group(2), radix)))
        except ValueError:               # an 8 or 9 in an octal read: not this radix
            pass
    return found


def examined(output, radix=8):
    return dict(examined_all(output, radix))
