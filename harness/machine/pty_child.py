"""Closing a pexpect child without pexpect's fixed pause.

pexpect (ptyprocess) sleeps delayafterclose (0.1 s) on every close, to give a
child it is about to kill time to exit. A simulator that has already quit (EOF
read) needs no such wait: reap it (as soon as it has exited: its pidfd says when)
and close at once. A scripted scenario spends about half its wall time in that
pause otherwise. kill(): SIGKILL, and the same.

And quitting SIMH: its QUIT FLUSHes the FORTH's UPDATEd blocks first and is
refused when they cannot be written (pdp11-devices/simh/leave_check.c).

And whether SIMH has the machine running: its sim> prompt reads the pty a line at
a time (the terminal edits the line); CONT puts the pty in raw mode, discarding
what was typed meanwhile (TCSAFLUSH, sim_console.c), and the machine gets each key."""
import os
import re
import select
import signal
import termios
import time

import pexpect

# leave_check.c's refusal: "QUIT refused: block(s) 300 UPDATEd and not written ..."
LEAVE_REFUSED = r"(?:QUIT|EXIT|BYE) refused: [^\r\n]*"


EXIT_GRACE_S = 5                    # a child whose EOF was read gets this long to exit


def exited(child, seconds):
    """Whether `child` has exited (and is reaped) within `seconds`."""
    if not child.isalive():
        return True
    try:
        pidfd = os.pidfd_open(child.pid)
    except OSError:                  # no pidfd (Linux before 5.3): a short poll
        deadline = time.monotonic() + seconds
        while child.isalive() and time.monotonic() < deadline:
            time.sleep(0.005)
        return not child.isalive()
    try:
        select.select([pidfd], [], [], seconds)
    finally:
        os.close(pidfd)
    return not child.isalive()


def close(child):
    """Close `child`, killing it if it still runs; no pause if it has exited or,
    its end of the pty read, is exiting."""
    if child.flag_eof:
        exited(child, EXIT_GRACE_S)
    if not child.isalive():
        child.delayafterclose = child.ptyproc.delayafterclose = 0
    child.close(force=True)


def kill(child):
    """SIGKILL `child` and close it, without pexpect's pauses."""
    if child.isalive():
        os.kill(child.pid, signal.SIGKILL)
        exited(child, EXIT_GRACE_S)
    close(child)


def quit_simh(child, timeout=15):
    """QUIT at sim>, and when the simulator refuses it (blocks it could not write,
    which the caller has reported or does not own), QUIT -F; waits for the exit.
    The refusal line, or None."""
    refused = LEAVE_REFUSED if child.encoding else LEAVE_REFUSED.encode()
    child.send("quit\n" if child.encoding else b"quit\n")      # LF ends a sim> line on any terminal
    if child.expect([pexpect.EOF, re.compile(refused)], timeout=timeout) == 0:
        return None
    line = child.match.group(0)
    child.send("quit -f\n" if child.encoding else b"quit -f\n")
    child.expect(pexpect.EOF, timeout=timeout)
    return line


def line_editing(fd):
    """Whether the terminal on `fd` (either end of a pty) edits lines (ICANON), as at
    SIMH's sim>; None when it is not a terminal (or is gone)."""
    try:
        return bool(termios.tcgetattr(fd)[3] & termios.ICANON)
    except (termios.error, OSError):
        return None
