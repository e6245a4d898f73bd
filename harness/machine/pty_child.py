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
# After CONT, at most this long until SIMH has put the pty out of sim>'s line
# editing (it flushes the pty as it does: TCSAFLUSH, sim_console.c)
CONT_WAIT_S = 2.0


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


def probe_prompt(child, tries=40):
    """After CONT: SIMH discards what was typed before the machine runs
    (TCSAFLUSH), so wait for that (the pty leaves sim>'s line editing; a pty that
    never edits lines, such as the console's own, has nothing to wait for) and type
    an empty line until the FORTH answers it.
    0 answered, 2 no answer, 3 the simulator exited. (A late answer to an
    earlier empty line may come after this returns: console_session's _flush and
    Machine.cont allow for it.)"""
    ok = " ok\r\n" if child.encoding else b" ok\r\n"   # str or bytes, as the child reads
    deadline = time.monotonic() + CONT_WAIT_S
    while line_editing(child.child_fd) and time.monotonic() < deadline:
        time.sleep(0.001)                          # no event says so: a short poll
    for _ in range(tries):
        child.send("\r")
        i = child.expect([ok, pexpect.TIMEOUT, pexpect.EOF], timeout=0.25)
        if i != 1:
            return 0 if i == 0 else 3
    return 2
