"""Closing a pexpect child without pexpect's fixed pause.

pexpect (ptyprocess) sleeps delayafterclose (0.1 s) on every close, to give a
child it is about to kill time to exit. A simulator that has already quit (EOF
read) needs no such wait: reap it and close at once. A scripted scenario spends
about half its wall time in that pause otherwise.

And quitting SIMH: its QUIT FLUSHes the FORTH's UPDATEd blocks first and is
refused when they cannot be written (pdp11-devices/simh/leave_check.c)."""
import re

import pexpect

# leave_check.c's refusal: "QUIT refused: block(s) 300 UPDATEd and not written ..."
LEAVE_REFUSED = r"(?:QUIT|EXIT|BYE) refused: [^\r\n]*"


def close(child):
    """Close `child`, killing it if it still runs; no pause if it has exited."""
    if not child.isalive():
        child.delayafterclose = child.ptyproc.delayafterclose = 0
    child.close(force=True)


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
