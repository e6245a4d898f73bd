"""The simulator behind the lab page: SIMH on a pty, and its two live streams.

The machine boots as in `make run`, with the plant trace (ATTACH PLANT) and the
LAB device (pdp11-devices/lab.c) attached to FIFOs in a private temporary
directory; a third FIFO carries the lab's commands (speed, pause, step, watch,
dump) to the LAB device. Everything is read on the asyncio loop, so the
simulator never waits for a reader. Leaving (BYE, ^D, or close()) is the
console's: FLUSH, detach, quit (harness/console_session.py).
"""
import asyncio
import os
import re
import tempfile
from pathlib import Path

import pexpect

from harness.console_session import CTRL_U, Leave, LineWatcher, leave
from harness.lab.feed import Lines, PlantRows, lab_row
from harness import simh
from harness.simh import MACHINE_INI

ROOT = Path(__file__).resolve().parents[2]
KERNEL = ROOT / "build" / "kernel.lda"
SAMPLES_PER_S = 120                   # plant trace rows per axis per simulated second
SPEEDS = {"real": 1, "x10": 10, "full": 0}
STOPS = re.compile(rb"^\s+([XYZT])\s+\S+\s+\S+\s+\S+\s+\S+\s+(-?[\d.]+)\s+(-?[\d.]+)\s+\S+\s*$",
                   re.M)
READ_CHUNK = 1 << 16


def end_stops(text):
    """{axis letter: (pmin, pmax)} from SHOW PLANT's parameter table."""
    return {m.group(1).decode(): (float(m.group(2)), float(m.group(3)))
            for m in STOPS.finditer(text)}


def plant_stops(simulator):
    """The end stops the plant powers up with (the lab's machine starts so)."""
    return end_stops(simh.run("show plant\n", simulator=simulator, timeout=30).encode())


def boot_script(disk, plant_fifo, lab_fifo, speed, kernel=KERNEL):
    return (f"do {MACHINE_INI}\n"
            f"attach rl0 {Path(disk).resolve()}\n"
            f"set plant sample={SAMPLES_PER_S}\n"
            f"attach plant {plant_fifo}\n"
            f"attach lab {lab_fifo}\n"
            f"set lab speed={speed}\n"
            f"load {kernel}\n"
            "go\n")


class Simulator:
    """One lab machine. Callbacks (called on the loop): console(bytes),
    plant(list of rows), lab(LabRow), ended(flushed: bool or None)."""

    def __init__(self, simulator, disk, console, plant, lab, ended, speed="real"):
        self.callbacks = console, plant, lab, ended
        self.simulator, self.disk, self.speed = simulator, disk, speed
        self.tmp = tempfile.TemporaryDirectory(prefix="lab-")
        self.watcher = LineWatcher()
        self.child = None
        self.fds = {}
        self.leaving = False
        self.stops = plant_stops(simulator)

    def start(self):
        loop = asyncio.get_running_loop()
        tmp = Path(self.tmp.name)
        plant_fifo, lab_fifo = tmp / "plant.csv", tmp / "lab"
        for fifo in (plant_fifo, lab_fifo, tmp / "lab.ctl"):
            os.mkfifo(fifo, 0o600)
        # Readers first (SIMH's open for writing waits for one); the command FIFO
        # is held open read-write so neither side's open waits for the other.
        self.fds["plant"] = os.open(plant_fifo, os.O_RDONLY | os.O_NONBLOCK)
        self.fds["lab"] = os.open(lab_fifo, os.O_RDONLY | os.O_NONBLOCK)
        self.ctl = os.open(tmp / "lab.ctl", os.O_RDWR | os.O_NONBLOCK)
        ini = tmp / "lab.ini"
        ini.write_text(boot_script(self.disk, plant_fifo, lab_fifo, SPEEDS[self.speed]))
        self.child = pexpect.spawn(str(self.simulator), [str(ini)], timeout=None,
                                   dimensions=(24, 80), cwd=str(ROOT))
        self.child.delaybeforesend = None
        plant_lines, lab_lines, rows = Lines(), Lines(), PlantRows()
        console, plant, lab, _ = self.callbacks

        def read_plant(data):
            parsed = [r for r in map(rows.parse, plant_lines.feed(data)) if r]
            if parsed:
                plant(parsed)

        def read_lab(data):
            for line in lab_lines.feed(data):
                row = lab_row(line)
                if row:
                    lab(row)

        self._watch(loop, "plant", read_plant)
        self._watch(loop, "lab", read_lab)
        self.fds["pty"] = self.child.child_fd
        self._watch(loop, "pty", console)

    def _watch(self, loop, name, handle):
        fd = self.fds[name]

        def readable():
            try:
                data = os.read(fd, READ_CHUNK)
            except BlockingIOError:
                return
            except OSError:
                data = b""
            if not data:
                self._unwatch(name)
                if name == "pty" and not self.leaving:
                    self.callbacks[3](None)           # the simulator exited by itself
                return
            handle(data)
        loop.add_reader(fd, readable)

    def _unwatch(self, name):
        fd = self.fds.pop(name, None)
        if fd is not None:
            asyncio.get_running_loop().remove_reader(fd)
            if name != "pty":
                os.close(fd)

    # ---- from the page ------------------------------------------------------------
    def keys(self, data):
        """What the user typed; BYE or ^D starts the way out."""
        if self.leaving:
            return
        try:
            self.watcher.feed(data)
        except Leave:                    # as the console: the BYE line is killed with ^U
            asyncio.get_running_loop().create_task(self.close())
            return
        os.write(self.child.child_fd, data)

    def command(self, text):
        """A line to the LAB device (speed X, pause, run, step, watch, dump)."""
        try:
            os.write(self.ctl, text.encode() + b"\n")
        except BlockingIOError:
            pass                                    # the device is not reading: dropped

    # ---- leaving --------------------------------------------------------------------
    async def close(self):
        """FLUSH, detach, quit, as the console does; then the `ended` callback."""
        if self.leaving or self.child is None:
            return
        self.leaving = True
        self.command("run")
        self._unwatch("pty")
        echo = _Echo(asyncio.get_running_loop(), self.callbacks[0])
        try:
            flushed = await asyncio.to_thread(self._leave, echo)
        finally:
            for name in list(self.fds):
                self._unwatch(name)
            os.close(self.ctl)
            self.child.close(force=True)
            self.tmp.cleanup()
        self.callbacks[3](flushed)

    def _leave(self, echo):
        if not self.child.isalive():
            return None
        try:
            self.child.send(CTRL_U)
            return leave(self.child, ("lab", "plant"), echo=echo)
        except (pexpect.TIMEOUT, pexpect.EOF, OSError):
            return False


class _Echo:
    """A binary 'file' for pexpect's logfile_read that hands what the machine
    prints to the page (from the leaving thread, onto the loop)."""

    def __init__(self, loop, console):
        self.loop, self.console = loop, console

    def write(self, data):
        self.loop.call_soon_threadsafe(self.console, bytes(data))

    def flush(self):
        pass
