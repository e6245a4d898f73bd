"""The interactive console: the user's terminal joined to the simulator's.

The user types to the FORTH (or, after ^E, to SIMH's sim> prompt) directly;
the harness watches the keystrokes only to catch the ways out
(harness/machine/console_watch.py): BYE, ^D, the halt of the FORTH's BYE word, and at sim>
^C, which would otherwise end the simulator with the FORTH's UPDATEd blocks unwritten.
(SIMH's QUIT, EXIT and BYE at sim> FLUSH the blocks inside the simulator,
pdp11-devices/simh/leave_check.c; the console then reports from its exit status:
simh_exit_report.) Then it erases the typed line (^U, which both the FORTH and SIMH's prompt take as
"kill line"), brings the FORTH back to its prompt if SIMH had it stopped, has it
FLUSH its block buffers, checks at sim> that no UPDATEd block is left (listing the
ones that are), detaches the trace and the disk, quits SIMH and says what happened.
"""
import contextlib
import os
import re
import select
import signal
import sys
import tempfile
import termios
import tty
from dataclasses import dataclass, field
from pathlib import Path

import pexpect

from harness.blocks.disk import DiskError, block_ranges, blocks_missing, read_image
from harness.machine import block_buffers, pty_child
from harness.machine import kernel_layout, simh
from harness.machine.build import KERNEL, PRISTINE_DISK
from harness.machine.console_halt import HaltWatcher
from harness.machine.console_watch import Leave, LineWatcher
from harness.machine.kernel_layout import KernelMapError, read_kernel_map
from harness.machine.key_feed import KeyFeed, shown
from harness.machine.pty_child import probe_prompt
from harness.machine.pty_spawn import Spawn

# the 11/23's pace (CLK RATE, 300K instructions/s) from the first instruction; SIMH's
# SET THROTTLE cannot pace the kernel's WAIT (pdp11-devices/bus/kw11l.c)
REALTIME = "set clk realtime"
# --fast: full speed while the FORTH works; while KEY WAITs the KW11-L sleeps the
# host at the 11/23's pace (pdp11-devices/bus/kw11l.c), so an idle prompt costs little
IDLE = "set cpu idle"
# ... or at IDLESPEED times that pace (--idle-speed): SET CLK IDLESPEED's range
IDLE_SPEED_MAX = 1000
# The amplifier rack starts switched off, as the lab's operator left it: the axes
# stand still (z's brake on) however long the blocks take to load or the user
# waits; it is switched on once Set.Up.Robot's servo holds them (README).
RACK_OFF = "set plant power=off"
# ... and says so at the console when a move waits on it (pdp11-devices/plant/rack_hint.c)
RACK_HINT_ON = "set plant hint=on"
CTRL_C, CTRL_E, CTRL_U = b"\x03", b"\x05", b"\x15"
BUSY_WAIT = 3                      # wall seconds a running word gets before ^C stops it
FLUSH_WAIT = 60                    # wall seconds the FORTH gets to answer FLUSH
HINT = ("Console: leave with BYE (or ^D; ^C, QUIT, EXIT or BYE at sim> too): the FORTH "
        "FLUSHes its blocks and the disk is detached. ^E gives SIMH's sim> prompt (SHOW PLANT, then "
        "CONT to come back).")
RACK_HINT = ("The amplifier rack starts OFF: the axes stand still. After Set.Up.Robot, "
             "switch it on: ^E, then SET PLANT POWER=ON, then CONT.")
SIMH_ERROR = re.compile(r"(Unit not attached|Non-existent[^\r\n]*|[A-Z][^\r\n]*error[^\r\n]*)")


def boot_script(disk, trace=None, fast=False, kernel=KERNEL, timed=False, read_only=False,
                setup="", idle_speed=1):
    """The console's machine: paced (or idling, its waits at `idle_speed` times the
    11/23's pace) as asked, the rack off, a trace; timed: each instruction takes its
    KDF11-A time (SET CLK TIMED); `setup`: more SIMH lines (the five machines'
    lock-step: harness/controllers/launcher.py)."""
    trace_line = f"attach plant {Path(trace).resolve()}\n" if trace else ""
    pace = f"{IDLE}\nset clk idlespeed={idle_speed}" if fast else REALTIME
    return simh.boot_script(disk, kernel, setup=f"{pace}\n"
                            + ("set clk timed\n" if timed else "")
                            + f"{RACK_OFF}\n{RACK_HINT_ON}\n{trace_line}" + setup,
                            read_only=read_only)


def simh_exit_report(status, disk):
    """(lines to say, exit status) when the simulator ended by itself with `status`."""
    if status == simh.DISK_HELD:                 # its own line said who holds the disk
        return [], 1
    if status == 0:
        return ["The simulator was left at sim> (QUIT, EXIT or BYE): it FLUSHed the "
                f"FORTH's UPDATEd blocks first (named above, if any) and closed {disk}."], 0
    if status == simh.LEFT_WITHOUT_BLOCKS:
        return [f"The simulator was left with QUIT -F: the blocks named above are NOT "
                f"SAVED in {disk}."], 1
    return ["the simulator exited on its own: blocks UPDATEd since the last FLUSH, if "
            f"any, were not written to {disk}"], 1


def say(*lines):
    try:
        sys.stdout.write("\r\n" + "".join(f"[console] {line}\r\n" for line in lines))
        sys.stdout.flush()
    except OSError:                  # the terminal has gone away: nobody to tell
        quiet_stdout()


def quiet_stdout():
    """Nobody reads a closed terminal, and writing to it fails: what would be
    printed goes nowhere rather than cutting a FLUSH short."""
    sys.stdout = open(os.devnull, "w")


@dataclass
class Departure:
    """What leaving did to the disk, for the report and the exit status."""
    disk: Path
    flush: str = "not sent"          # "ok", or what happened: "failed (Error: ...)", ...
    unwritten: list = None           # UPDATEd blocks left in the buffers (None: unknown)
    detach: str = "not tried"        # "ok" or why not
    notes: list = field(default_factory=list)

    @property
    def safe(self):
        return self.flush == "ok" and self.unwritten == [] and self.detach == "ok"

    def report(self):
        if self.flush == "ok" and self.unwritten == []:
            lines = [f"FLUSH answered ok: every UPDATEd block is written to {self.disk} "
                     "and synced to the host's disk."]
        elif self.flush == "ok":
            lines = ["FLUSH answered ok, " + ("yet the FORTH's buffers could not be read "
                                              "back to confirm it." if self.unwritten is None
                                              else "yet blocks are still UPDATEd:")]
        else:
            lines = [f"FLUSH {self.flush}." if self.flush != "not sent" else
                     "FLUSH could not be sent (the FORTH never came back to its prompt)."]
        if self.unwritten:
            lines.append(f"NOT SAVED: block(s) {block_ranges(self.unwritten)}: UPDATEd, "
                         "and FLUSH did not complete their write; the changes may be lost.")
        elif self.unwritten is None and self.flush != "ok":
            lines.append("Blocks UPDATEd since the last FLUSH may not be written "
                         "(the FORTH's buffers could not be read).")
        lines.append(f"Disk {self.disk} detached." if self.detach == "ok" else
                     f"Disk {self.disk} not detached: {self.detach}.")
        return self.notes + lines


def bye_halt(kernel=KERNEL):
    """What SIMH prints when the kernel's BYE word halts at (BYE), or None."""
    try:
        bye = read_kernel_map(Path(kernel).with_suffix(".map")).get("(BYE)")
    except KernelMapError:
        return None
    return None if bye is None else b"HALT instruction, PC: %06o" % (bye + 2)


def _to_forth_prompt(child, gone, busy_wait):
    """Bring the FORTH to its prompt; 0 at the prompt, 2 no answer, 3 exited."""
    child.send(CTRL_U + b"\r\n")                # an empty line: who answers? (the FORTH
                                                 # takes CR LF as one line end; sim> may end lines on LF only)
    i = child.expect([b" ok\r\n", b"sim> ", pexpect.TIMEOUT, pexpect.EOF,
                      b" compiled\r\n"], timeout=busy_wait)
    if i == 1:                                   # SIMH had the machine stopped
        child.send(b"nobreak all\n")             # a breakpoint would stop it again
        child.expect(b"sim> ", timeout=15)
        child.send(b"cont\n")
        return probe_prompt(child)
    if i == 4:                                   # FLUSH typed now would be compiled
        gone.notes.append("A definition was still open: ^C discarded it so that "
                          "FLUSH could run.")
        child.send(CTRL_C)
        return probe_prompt(child)
    if i == 2:                                   # a word is running: stop it as a user would
        gone.notes.append(f"The FORTH was busy for {busy_wait:g} s: ^C stopped the "
                          "running word so that FLUSH could run.")
        child.send(CTRL_C)
        return probe_prompt(child)
    return i


def _flush(child):
    """FLUSH's answer. Empty lines typed to find the prompt may still be answered
    after it is sent, so the answer counted is the one after FLUSH's own echo."""
    child.send(b"FLUSH\r")
    answers = [b" ok\r\n", rb"(Error: [^\r]*)\r\n", pexpect.TIMEOUT, pexpect.EOF]
    i = child.expect([b"FLUSH"] + answers[2:], timeout=FLUSH_WAIT)
    if i == 0:
        i = child.expect(answers, timeout=FLUSH_WAIT)
    else:
        i += 1
    if i == 1:
        return f"failed ({child.match.group(1).decode('latin-1')})"
    return {0: "ok", 2: f"was not answered within {FLUSH_WAIT} s (the FORTH is busy)",
            3: "was cut short: the simulator exited"}[i]


def _simh(child, command):
    child.send(command.encode() + b"\n")          # LF ends a sim> line on any terminal
    child.expect(b"sim> ", timeout=15)
    return child.before.decode("latin-1")


def _unwritten(child, kernel):
    try:
        symbols = read_kernel_map(Path(kernel).with_suffix(".map"))
    except KernelMapError:
        return None
    return block_buffers.read_unwritten(symbols, lambda command: _simh(child, command))


def _detach(child, unit):
    """"ok", or why the unit was not detached (SIMH detaches an unattached unit
    silently, so SHOW says first whether there is anything to detach)."""
    if "not attached" in _simh(child, f"show {unit}"):
        return "it was not attached (a DETACH at sim>, or an ATTACH that failed)"
    found = SIMH_ERROR.search(_simh(child, f"detach {unit}"))
    return found.group(1) if found else "ok"


def leave(child, disk, trace, kernel=KERNEL, busy_wait=BUSY_WAIT, devices=(), echo=None):
    """Flush the FORTH's blocks, check, detach (the trace, then `devices`, then
    the disk), quit; the Departure. What the FORTH prints meanwhile goes to
    `echo` (a binary file; default stdout)."""
    gone = Departure(Path(disk))
    child.logfile_read = echo or sys.stdout.buffer   # the user sees what happens
    try:
        if _to_forth_prompt(child, gone, busy_wait) == 0:
            gone.flush = _flush(child)
        child.logfile_read = None                # the checks below are the harness's own
        if not child.isalive():
            gone.detach = "the simulator had exited (SIMH closed the image itself)"
            return gone
        child.send(CTRL_E)
        child.expect(b"sim> ", timeout=15)
        gone.unwritten = _unwritten(child, kernel)
        for unit in (("plant",) if trace else ()) + tuple(devices):
            _detach(child, unit)
        gone.detach = _detach(child, "rl0")
        pty_child.quit_simh(child)       # the report names the blocks a refusal would
    except (pexpect.TIMEOUT, pexpect.EOF) as err:
        gone.notes.append(f"the simulator stopped answering while leaving "
                          f"({type(err).__name__})")
        if gone.detach == "not tried":
            gone.detach = "the simulator stopped answering"
    return gone


HANGUP = "the terminal closed"
PUMP_S = 0.005                     # how often waiting keys are offered to the pty


def _on_hangup(signum, frame):
    raise Leave(HANGUP)


def _raw(fd):
    """The terminal in raw mode, as SIMH's console wants it; the mode to restore."""
    if not os.isatty(fd):
        return None
    saved = termios.tcgetattr(fd)
    tty.setraw(fd, termios.TCSANOW)           # what was typed before is kept
    return saved


def _restore(fd, saved):
    if saved is not None:
        try:
            termios.tcsetattr(fd, termios.TCSAFLUSH, saved)
        except termios.error:
            pass                             # the terminal has gone away


def _converse(child, feed, watcher, halts, log=None):
    """The user's terminal joined to the simulator's, until the simulator exits
    (returns) or the user leaves (Leave). Keys go through `feed`, never with a
    blocking write: the machine's output is read all the while. The end of
    input (the terminal closed) is a way out like BYE, so the FORTH still
    FLUSHes. `log`: a binary file that gets a copy of what the terminal shows."""
    fd_in, fd_out, fd_sim = sys.stdin.fileno(), sys.stdout.fileno(), child.child_fd
    saved = _raw(fd_in)
    try:
        while True:
            ready, _, _ = select.select([fd_in, fd_sim], [], [], PUMP_S if feed.queue else None)
            if fd_sim in ready:
                try:
                    data = os.read(fd_sim, 1 << 16)
                except OSError:
                    data = b""
                if not data:
                    child.flag_eof = True            # as pexpect notes its own reads' end
                    return
                feed.output(data)
                data = shown(halts.feed(watcher.output(data)))
                _show(fd_out, data)
                if log is not None:
                    log.write(data)
                    log.flush()
            if fd_in in ready:
                data = os.read(fd_in, 1 << 16)
                if not data:
                    raise Leave(HANGUP)
                for note in feed.typed(data, watcher):
                    say(note)
            feed.pump(watcher)
    finally:
        _restore(fd_in, saved)


def _show(fd, data):
    try:
        os.write(fd, data)
    except OSError:
        pass                                 # nobody reads a closed terminal


def missing_blocks_note(disk, pristine=PRISTINE_DISK):
    """One line when `disk` lacks blocks the pristine image has (a working disk made
    by an older version: make never overwrites it), else None."""
    try:
        work, shipped = read_image(disk), read_image(pristine)
    except DiskError:
        return None                          # the boot itself says what is wrong
    missing = [] if work == shipped else blocks_missing(work, shipped)   # a copy lacks none
    if not missing:
        return None
    return (f"{disk} lacks blocks {block_ranges(missing)}, which this version ships (they "
            "are blank on it). After BYE, python -m harness disk add-new copies them in "
            "without touching a block you wrote.")


def session(simulator, disk, trace=None, fast=False, kernel=KERNEL, busy_wait=BUSY_WAIT,
            timed=False, read_only=False, setup="", rack_hint=True, log=None, idle_speed=1):
    """Run the console until the user leaves; the exit status (0: all written).
    `setup`: more SIMH lines for the boot script (boot_script); `rack_hint`: say that
    the rack starts off (not where another plant drives the axes); `log`: a file that
    gets a copy of what the terminal shows (the five machines' page reads it);
    `idle_speed`: with `fast`, the pace of the FORTH's waits (boot_script)."""
    with tempfile.TemporaryDirectory(prefix="console-") as tmp:
        ini = Path(tmp) / "console.ini"
        ini.write_text(boot_script(disk, trace, fast, kernel, timed, read_only, setup,
                                   idle_speed))
        waits = "" if idle_speed == 1 else f", its waits at {idle_speed} times the 11/23's pace"
        pace = f"full speed{waits}" if fast else (
            "real-time pace (KDF11-A instruction times)" if timed
            else "real-time pace (300K instructions/s)")
        mode = " (read-only: FLUSH will fail)" if read_only else ""
        print(f"[console] booting the FORTH on the PDP-11/23, {pace}, disk {disk}{mode}")
        print(f"[console] {HINT}")
        if rack_hint:
            print(f"[console] {RACK_HINT}")
        note = missing_blocks_note(disk)
        if note:
            print(f"[console] {note}")
        sys.stdout.flush()
        size = os.get_terminal_size() if sys.stdout.isatty() else os.terminal_size((80, 24))
        child = Spawn(str(simulator), [str(ini)], timeout=None,
                      dimensions=(size.lines, size.columns))
        child.delaybeforesend = None
        watcher = LineWatcher(bye_halt(kernel))
        feed = KeyFeed(child.child_fd, child.pid)
        hangup = signal.signal(signal.SIGHUP, _on_hangup)
        try:
            halts = HaltWatcher(kernel, kernel_layout.entry(Path(kernel).with_suffix(".map")) or 0)
            with open(log, "ab") if log else contextlib.nullcontext() as copy:
                _converse(child, feed, watcher, halts, copy)
        except Leave as way:
            signal.signal(signal.SIGHUP, signal.SIG_IGN)     # leaving: no second hangup
            if way.how == HANGUP:
                quiet_stdout()
            if way.how != "BYE":
                say(f"{way.how}: leaving; the FORTH FLUSHes its blocks first")
            child.send(way.typed)                # typed ahead of the way out
            left = feed.discard()
            if left:
                say(f"{left} characters typed after the way out were not sent to the machine")
            gone = leave(child, disk, trace, kernel, busy_wait)
            say(*gone.report(), "Bye.")
            return 0 if gone.safe else 1
        finally:
            signal.signal(signal.SIGHUP, hangup)
            pty_child.close(child)
        lines, status = simh_exit_report(child.exitstatus, disk)
        if lines:
            say(*lines)
        return status
