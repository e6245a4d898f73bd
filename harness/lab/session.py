"""The simulator behind the lab page: SIMH on a pty, and the LAB device's stream.

The machine boots as in `make run`, with the LAB device (pdp11-devices/lab/lab.c)
attached to a FIFO in a private temporary directory; a second FIFO carries the
lab's commands (speed, pause, step, watch, dump) to the device. Everything is
read on the asyncio loop, so the simulator never waits long for a reader.
Leaving (BYE, ^D, ^C at sim>, the FORTH's BYE word, or close()) is the console's:
FLUSH, check, detach, quit (harness/machine/console_session.py). SIMH's QUIT,
EXIT or BYE typed at the page's sim> FLUSH inside the simulator
(pdp11-devices/simh/leave_check.c); the lab then reports from its exit status.
Keys go through a KeyFeed (harness/machine/key_feed.py): never a blocking write,
a bounded queue (QUEUE_LIMIT) whose room the pages are told.
A lab's temporary directory holds lab.pid; a new lab removes the directories of
labs whose process is gone (killed, so they could not clean up).
"""
import asyncio
import fcntl
import os
import shutil
import sys
import tempfile
from pathlib import Path

from harness.lab.feed import Lines
from harness.lab.sim_prompt_guard import SimPromptGuard, prompt_termios
from harness.lab.protocol import device_command
from harness.machine import plant_rows, pty_child, simh
from harness.machine.build import KERNEL, ROOT
from harness.machine.console_session import (RACK_OFF, bye_halt, leave, say,
                                             simh_exit_report)
from harness.machine.console_watch import SIM_PROMPT, Leave, LineWatcher
from harness.machine.key_feed import KeyFeed, shown
from harness.machine.pty_spawn import Spawn
from harness.machine.simh_command import RUNS, simh_command

SPEEDS = {"real": 1, "x10": 10, "full": 0}
READ_CHUNK = 1 << 16
LAB_READ_PAUSE_S = 0.02      # the LAB FIFO: at most ~50 reads a second, not one per tick
                             # (600 at x10); its pipe holds 64 KB, 90 ms of rows at x10
UNWATCHED_READ_PAUSE_S = 0.1 # ... while no page looks, if the pipe could be grown to
PIPE_BYTES = 1 << 20         # this (1.5 s of rows at x10): an idle lab's wake-ups were
                             # half its CPU, and only a page wants the rows soon
QUEUE_LIMIT = 1 << 16        # characters waiting for the simulator; the pages send within it
PUMP_S = 0.005               # how often waiting keys are offered to the pty
EXIT_WAIT_S = 0.1            # for a simulator that has quit, before its pty is closed
TMP_PREFIX = "lab-"


def remove_stale(tmp_root=None):
    """Remove the temporary directories of labs whose process is gone; their names."""
    removed = []
    for folder in Path(tmp_root or tempfile.gettempdir()).glob(f"{TMP_PREFIX}*"):
        try:
            pid = int((folder / "lab.pid").read_text())
        except (OSError, ValueError):
            continue                              # not a lab's, or not ours to judge
        if not _alive(pid):
            shutil.rmtree(folder, ignore_errors=True)
            removed.append(folder.name)
    return removed


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def boot_script(disk, lab_fifo, speed, kernel=KERNEL, read_only=False, timed=False):
    """The lab's machine: the LAB device on its FIFO, the rack off as in make run
    (the page has the switch); timed: on the 11/23's clock (SET CLK TIMED, before
    the LAB device's first tick is scheduled, so its ticks fall on the clock's)."""
    return simh.boot_script(disk, kernel, setup=("set clk timed\n" if timed else "")
                            + f"attach lab {lab_fifo}\nset lab speed={speed}\n{RACK_OFF}\n",
                            read_only=read_only)


class Simulator:
    """One lab machine. Callbacks (called on the loop): console(bytes), lab(the
    LAB device's whole lines as read, one bytes block: feed.py decodes them),
    ended(safe: bool, or None when the simulator exited by itself)."""

    def __init__(self, simulator, disk, console, lab, ended, speed="real", page=None,
                 read_only=False, watched=None, timed=False):
        self.callbacks = console, lab, ended
        self.page = page or console               # the leaving report: the page's copy
        self.watched = watched or (lambda: True)  # whether a page looks (the FIFO's pace)
        self.simulator, self.disk, self.speed = simulator, disk, speed
        self.read_only, self.timed = read_only, timed
        remove_stale()
        self.tmp = tempfile.TemporaryDirectory(prefix=TMP_PREFIX)
        (Path(self.tmp.name) / "lab.pid").write_text(str(os.getpid()))
        self.watcher = LineWatcher(bye_halt(KERNEL))
        self.feed = None
        self.keys_waiting = None
        self.guard = SimPromptGuard(self.watcher)     # the page's keys pass through it
        self.prompted = asyncio.Event()              # SIMH printed its prompt (simh_lines)
        self.capture = None                          # what SIMH prints, while simh_lines reads it
        self.simh_turn = asyncio.Lock()              # one simh_lines at a time: they share it
        self._tail = b""
        self.child = None
        self.fds = {}
        self.leaving = False
        self.plant = plant_rows.layout(simulator)     # the lab's machine starts so
        self.stops = self.plant.stops

    def start(self):
        loop = asyncio.get_running_loop()
        tmp = Path(self.tmp.name)
        lab_fifo = tmp / "lab"
        for fifo in (lab_fifo, tmp / "lab.ctl"):
            os.mkfifo(fifo, 0o600)
        # The reader first (SIMH's open for writing waits for one); the command FIFO
        # is held open read-write so neither side's open waits for the other.
        self.fds["lab"] = os.open(lab_fifo, os.O_RDONLY | os.O_NONBLOCK)
        self.ctl = os.open(tmp / "lab.ctl", os.O_RDWR | os.O_NONBLOCK)
        ini = tmp / "lab.ini"
        ini.write_text(boot_script(self.disk, lab_fifo, SPEEDS[self.speed],
                                   read_only=self.read_only, timed=self.timed))
        self.child = Spawn(str(self.simulator), [str(ini)], timeout=None,
                           dimensions=(24, 80), cwd=str(ROOT),
                           tty_setup=prompt_termios)
        self.child.delaybeforesend = None
        self.feed = KeyFeed(self.child.child_fd, self.child.pid, limit=QUEUE_LIMIT)
        self.keys_waiting = asyncio.Event()
        self.pumping = loop.create_task(self._pump())
        lab_lines = Lines()
        console, lab, _ = self.callbacks
        roomy = _grow_pipe(self.fds["lab"])
        self._watch(loop, "lab", lambda data: lab(lab_lines.feed(data)),
                    lambda: LAB_READ_PAUSE_S if self.watched() or not roomy
                    else UNWATCHED_READ_PAUSE_S)
        self.fds["pty"] = self.child.child_fd

        def read_console(data):
            at_prompt = self.watcher.at_simh
            if self.capture is not None:
                self.capture += data
            self._tail = (self._tail + data)[-len(SIM_PROMPT):]
            if self._tail == SIM_PROMPT:
                self.prompted.set()
            try:
                self.watcher.output(data)         # is SIMH's sim> up? the BYE word's halt?
                self.feed.output(data)            # booted yet?
                self.feed.held(self.watcher)      # the queue follows sim> coming and going
            except Leave as way:
                console(shown(data))
                loop.create_task(self.close(way.how))
                return
            console(shown(data))
            self.keys_waiting.set()               # what waited for the boot may go
            if self.watcher.at_simh and not at_prompt:
                self.page_keys(b"")               # the page's keys that waited for sim>
        self._watch(loop, "pty", read_console)

    def _watch(self, loop, name, handle, pause=None):
        """Hand what `name`'s fd gives to `handle`; with `pause` (() -> seconds),
        after a read that did not fill READ_CHUNK, that long without reading:
        meanwhile the writer's rows gather in the FIFO, and one wake-up takes many."""
        fd = self.fds[name]

        def resume():
            if self.fds.get(name) == fd:          # not closed meanwhile
                loop.add_reader(fd, readable)

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
                    self.leaving = True               # the simulator exited by itself
                    self.keys_waiting.set()
                    self._release()
                    self.callbacks[2](self._exited())
                return
            handle(data)
            if pause and len(data) < READ_CHUNK and self.fds.get(name) == fd:
                loop.remove_reader(fd)
                loop.call_later(pause(), resume)
        loop.add_reader(fd, readable)

    def _unwatch(self, name):
        fd = self.fds.pop(name, None)
        if fd is not None:
            asyncio.get_running_loop().remove_reader(fd)
            if name != "pty":
                os.close(fd)

    # ---- from the page ------------------------------------------------------------
    def keys(self, data):
        """What the lab's own shell typed: the full SIMH console. Notes for the user
        (what ^C dropped). A way out (BYE, ^D, ^C at sim>:
        harness/machine/console_watch.py) starts leaving, as the console does. At
        sim> an Enter (CR) goes as the LF that ends a line there (prompt_termios)."""
        notes, start = [], 0
        for i, byte in enumerate(data):
            if byte == 13 and self.watcher.at_simh:
                notes += self._typed(data[start:i] + b"\n")
                start = i + 1
        return notes + self._typed(data[start:])

    def page_keys(self, data):
        """What the page typed: through the guard (harness/lab/sim_prompt_guard.py),
        which lets only the page's commands reach sim>; notes for the user."""
        if self.leaving or self.feed is None:
            return []
        notes = []
        try:
            while True:
                for kind, payload in self.guard.keys(data):
                    if kind == "page":
                        self.page(payload)
                    else:
                        notes += self._typed(payload)
                data = b""
                if not self.guard.more():        # a checked sim> line went: the rest now
                    return notes
        except Leave as way:
            self._way_out(way)
            return notes

    def _typed(self, data):
        if self.leaving or self.feed is None or not data:
            return []
        try:
            notes = self.feed.typed(data, self.watcher)
        except Leave as way:
            self._way_out(way)
            return []
        self.keys_waiting.set()
        return notes

    async def simh_lines(self, lines, wait_s=10, stop=True):
        """Type `lines` at sim> as the page would (through the guard), after
        stopping the machine when it runs (the LAB device's `halt`: at a tick, and
        answered while paused, when a ^E would wait for Run), or, with stop False,
        after SIMH's prompt comes by itself (a breakpoint was reported); a line
        that runs the machine (CONT) ends the list, but for STEP, which comes back
        to sim>. What SIMH printed for the last line answered at its prompt.
        Calls take turns (a step pressed while a breakpoint's history is read):
        each has SIMH's prompt and the capture to itself."""
        async with self.simh_turn:
            return await self._simh_lines(lines, wait_s, stop)

    async def _simh_lines(self, lines, wait_s, stop):
        if self.leaving or self.child is None:
            return ""
        if not self.watcher.at_simh:
            if stop:
                self.prompted.clear()
                self.command("halt")
            await asyncio.wait_for(self.prompted.wait(), wait_s)
        answer = ""
        for line in lines:
            self.prompted.clear()
            self.capture = bytearray()
            self.page_keys(line.encode() + b"\r")
            if simh_command(line) in RUNS - {"STEP"}:
                break
            await asyncio.wait_for(self.prompted.wait(), wait_s)
            answer = self.capture.decode("latin-1")
        self.capture = None
        return answer

    def room(self):
        return self.feed.room() if self.feed else 0

    def waiting(self):
        return self.feed.waiting() if self.feed and not self.leaving else 0

    def erase_line(self):
        """A new holder of the keyboard starts on an empty line: ^U after what the
        previous one left unfinished (queued, or typed and not ended)."""
        if self.feed and (self.watcher.line or (self.feed.queue and
                                                self.feed.queue[-1:] not in (b"\r", b"\n"))):
            self.keys(b"\x15")

    async def _pump(self):
        while not self.leaving:
            try:
                self.feed.pump(self.watcher)
            except Leave as way:
                self._way_out(way)
                return
            if self.feed.queue:
                await asyncio.sleep(PUMP_S)
            else:
                self.keys_waiting.clear()
                await self.keys_waiting.wait()

    def _way_out(self, way):
        os.write(self.child.child_fd, way.typed)     # typed ahead of the way out
        asyncio.get_running_loop().create_task(self.close(way.how))

    def command(self, text):
        """A line to the LAB device (protocol.DEVICE_COMMANDS; another is Refused)."""
        device_command(text)
        try:
            os.write(self.ctl, text.encode() + b"\n")
        except BlockingIOError:
            pass                                    # the device is not reading: dropped

    # ---- leaving --------------------------------------------------------------------
    async def close(self, how="BYE"):
        """FLUSH, check, detach, quit, as the console does; the report goes to the
        page and the shell; then the `ended` callback with True when every block
        was written (None when the simulator had already exited)."""
        if self.leaving or self.child is None:
            return
        self.leaving = True
        self.keys_waiting.set()                     # the pump ends
        left = self.feed.discard()
        self.command("run")
        self._unwatch("pty")
        loop = asyncio.get_running_loop()
        echo, page = _Echo(loop, self.callbacks[0]), _Echo(loop, self.page)
        try:
            safe = await asyncio.to_thread(self._leave, how, echo, page, left)
        except Exception as err:                # the lab must end all the same
            print(f"[lab] leaving went wrong: {err}", file=sys.stderr)
            safe = False
        finally:
            self._release()
        self.callbacks[2](safe)

    def _exited(self):
        """The simulator ended by itself (SIMH's QUIT at the page's sim>, a refused
        disk, a crash): the report, to the shell and the page; True when its exit
        status says every UPDATEd block was written, None when nothing is known."""
        code = self.child.exitstatus
        lines, status = simh_exit_report(code, self.disk)
        known = code in (0, simh.LEFT_WITHOUT_BLOCKS, simh.DISK_HELD)
        if lines:
            if known:                             # else the lab command says it
                say(*lines)
            self.page("".join(f"\r\n[lab] {line}" for line in lines).encode() + b"\r\n")
        return status == 0 if known else None

    def _release(self):
        for name in list(self.fds):
            self._unwatch(name)
        os.close(self.ctl)
        pty_child.exited(self.child, EXIT_WAIT_S)   # one that has quit is on its way out:
        pty_child.close(self.child)                 # no fixed pause for it
        self.tmp.cleanup()

    def _leave(self, how, echo, page, left):
        if not self.child.isalive():
            return None
        if how != "BYE":
            say(f"{how}: leaving; the FORTH FLUSHes its blocks first")
        gone = leave(self.child, self.disk, None, devices=("lab",), echo=echo)
        report = gone.report() + ["Bye."]
        if left:
            report.insert(0, f"{left} characters typed or pasted were still waiting: "
                          "not sent to the machine.")
        say(*report)
        page.write("".join(f"\r\n[lab] {line}" for line in report).encode() + b"\r\n")
        return gone.safe


def _grow_pipe(fd):
    """Let the FIFO hold PIPE_BYTES (Linux's F_SETPIPE_SZ); whether it does."""
    try:
        return fcntl.fcntl(fd, fcntl.F_SETPIPE_SZ, PIPE_BYTES) >= PIPE_BYTES
    except (OSError, AttributeError):            # not Linux, or above pipe-max-size
        return False


class _Echo:
    """A binary 'file' for pexpect's logfile_read that hands what the machine
    prints to the page (from the leaving thread, onto the loop)."""

    def __init__(self, loop, console):
        self.loop, self.console = loop, console

    def write(self, data):
        self.loop.call_soon_threadsafe(self.console, shown(bytes(data)))

    def flush(self):
        pass
