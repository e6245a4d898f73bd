"""The interactive console: the user's terminal joined to the simulator's.

The user types to the FORTH (or, after ^E, to SIMH's sim> prompt) directly;
the harness watches the keystrokes only to catch the way out: a line reading
BYE, or ^D. Then it erases that line (^U, which both the FORTH and SIMH's
prompt take as "kill line"), brings the FORTH back to its prompt if SIMH had
it stopped, has it FLUSH its block buffers, and detaches the trace and the
disk before quitting SIMH, so nothing typed into blocks is lost.
"""
import os
import sys
import tempfile
from pathlib import Path

import pexpect

from harness.simh import MACHINE_INI

KERNEL = Path(__file__).resolve().parent.parent / "build" / "kernel.lda"
THROTTLE = "set throttle 300K"     # the KDF11-A's rate, as SET CLK RATE's default
CTRL_D, CTRL_E, CTRL_U = b"\x04", b"\x05", b"\x15"
HINT = ("Console: leave with BYE (or ^D): the FORTH FLUSHes its blocks and the disk is "
        "detached. ^E gives SIMH's sim> prompt (SHOW PLANT, then CONT to come back).")


class Leave(Exception):
    """The user asked to leave."""


class LineWatcher:
    """Follows what the user types, line by line, to spot BYE and ^D."""

    def __init__(self):
        self.line = bytearray()

    def feed(self, data):
        """Raise Leave when `data` ends a line reading BYE or holds ^D."""
        for byte in data:
            if byte == CTRL_D[0]:
                raise Leave
            if byte in (13, 10):
                typed, self.line = self.line.decode("latin-1"), bytearray()
                if typed.strip().upper() == "BYE":
                    raise Leave
            elif byte in (8, 127):
                del self.line[-1:]
            elif byte in (CTRL_U[0], CTRL_E[0]):
                self.line.clear()
            elif byte >= 32:
                self.line.append(byte)
        return data


def boot_script(disk, trace=None, fast=False, kernel=KERNEL):
    return (f"do {MACHINE_INI}\n"
            + ("" if fast else THROTTLE + "\n")
            + f"attach rl0 {Path(disk).resolve()}\n"
            + (f"attach plant {Path(trace).resolve()}\n" if trace else "")
            + f"load {kernel}\n"
            "go\n")


def say(text):
    sys.stdout.write(f"\r\n[console] {text}\r\n")
    sys.stdout.flush()


def probe_prompt(child, tries=20):
    """After CONT: SIMH discards what was typed before the machine runs
    (TCSAFLUSH), so type an empty line until the FORTH answers it.
    0 answered, 2 no answer, 3 the simulator exited."""
    ok = " ok\r\n" if child.encoding else b" ok\r\n"   # str or bytes, as the child reads
    for _ in range(tries):
        child.send("\r")
        i = child.expect([ok, pexpect.TIMEOUT, pexpect.EOF], timeout=0.5)
        if i != 1:
            return 0 if i == 0 else 3
    return 2


def leave(child, detach=(), echo=None):
    """Flush the FORTH's blocks, detach the devices named in `detach` and then the
    disk, quit. What the machine prints goes to `echo` (a binary file; default
    stdout). Returns True if FLUSH was answered."""
    child.logfile_read = echo or sys.stdout.buffer   # the user sees what happens
    child.send(CTRL_U + b"\r")                   # an empty line: who answers?
    i = child.expect([b" ok\r\n", b"sim> ", pexpect.TIMEOUT, pexpect.EOF], timeout=15)
    if i == 1:                                   # SIMH had the machine stopped
        child.send(b"cont\r")
        i = probe_prompt(child)
    flushed = False
    if i == 0:
        child.send(b"FLUSH\r")
        flushed = child.expect([b" ok\r\n", b"Error: [^\r]*", pexpect.TIMEOUT,
                                pexpect.EOF], timeout=60) == 0
    if i == 3 or not child.isalive():
        say("the simulator had already exited; the disk was closed by SIMH without FLUSH")
        return False
    if not flushed:
        say("the FORTH did not answer FLUSH: blocks UPDATEd since the last FLUSH may be lost")
    child.send(CTRL_E)
    child.expect(b"sim> ", timeout=15)
    for device in detach:
        child.send(f"detach {device}\r".encode())
        child.expect(b"sim> ", timeout=15)
    child.send(b"detach rl0\r")
    child.expect(b"sim> ", timeout=15)
    child.send(b"quit\r")
    child.expect(pexpect.EOF, timeout=15)
    return flushed


def session(simulator, disk, trace=None, fast=False):
    """Run the console until the user leaves; the exit status."""
    with tempfile.TemporaryDirectory(prefix="console-") as tmp:
        ini = Path(tmp) / "console.ini"
        ini.write_text(boot_script(disk, trace, fast))
        pace = "full speed" if fast else "real-time pace (300K instructions/s)"
        print(f"[console] booting the FORTH on the PDP-11/23, {pace}, disk {disk}")
        print(f"[console] {HINT}")
        sys.stdout.flush()
        size = os.get_terminal_size() if sys.stdout.isatty() else os.terminal_size((80, 24))
        child = pexpect.spawn(str(simulator), [str(ini)], timeout=None,
                              dimensions=(size.lines, size.columns))
        child.delaybeforesend = None
        watcher = LineWatcher()
        try:
            child.interact(escape_character=None, input_filter=watcher.feed)
        except Leave:
            flushed = leave(child, ("plant",) if trace else ())
            say(("blocks flushed; " if flushed else "") + f"disk {disk} detached. Bye.")
            return 0 if flushed else 1
        finally:
            child.close(force=True)
        say("the simulator exited (blocks are FLUSHed only when you leave with BYE or ^D)")
        return 0
