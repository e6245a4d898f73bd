"""harness/machine/pty_spawn.py: a child started without forking the test's
process gets what pexpect's own start gives it: a session of its own with the
pty as its controlling terminal (so ^C and SIMH's ^E arrive as signals), the
size and echo asked for, the terminal modes of tty_setup, no stray descriptors,
and pexpect's exit status."""
import signal
import sys
import termios

import pexpect

from harness.machine.pty_spawn import Spawn

REPORT = """
import os, termios
def is_open(fd):
    try:
        return os.fstat(fd) is not None
    except OSError:
        return False
fds = [fd for fd in range(3, 256) if is_open(fd)]
os.open("/dev/tty", os.O_RDWR)                # fails without a controlling terminal
mode = termios.tcgetattr(0)
print("session", os.getsid(0) == os.getpid() == os.getpgrp(),
      "tty", os.ttyname(0) == os.ttyname(1) == os.ttyname(2),
      "size", *os.get_terminal_size(0),
      "echo", bool(mode[3] & termios.ECHO),
      "intr", mode[6][termios.VINTR],
      "fds", fds)
"""


def report(**options):
    child = Spawn(sys.executable, ["-c", REPORT], encoding="latin-1", timeout=20, **options)
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0, child.before
    return child.before.strip().splitlines()[-1]


def test_the_child_has_its_own_session_and_the_pty_as_its_terminal():
    line = report(dimensions=(24, 200))
    assert line.startswith("session True tty True size 200 24 echo True")
    assert line.endswith("fds []")


def test_echo_off_and_tty_setup_are_set_before_the_child_starts():
    def ctrl_e_interrupts(fd):
        mode = termios.tcgetattr(fd)
        mode[6][termios.VINTR] = b"\x05"
        termios.tcsetattr(fd, termios.TCSANOW, mode)
    line = report(echo=False, tty_setup=ctrl_e_interrupts)
    assert " echo False intr b'\\x05' " in line


def test_the_interrupt_key_signals_the_child_and_its_status_is_read():
    # Short sleeps: a SIGINT that lands after print() returns and before one long
    # sleep() starts is only acted on when that sleep ends (Python checks for signals
    # between bytecodes, and a sleep is interrupted only by a signal that comes while
    # it sleeps); under load it did, once in some 20 suite runs, after the 20 s limit.
    child = Spawn(sys.executable, ["-c", "import time\nprint('up', flush=True)\n"
                                   "while True: time.sleep(0.05)"], timeout=20)
    child.expect(b"up")
    child.sendintr()
    child.expect(pexpect.EOF)
    child.close()
    assert child.signalstatus == signal.SIGINT or "KeyboardInterrupt" in child.before.decode()
    assert not child.isalive()


def test_a_preexec_fn_still_runs_in_the_child():
    child = Spawn(sys.executable, ["-c", "import os; print(os.environ['MARK'])"],
                  preexec_fn=lambda: __import__("os").environ.__setitem__("MARK", "set"),
                  encoding="latin-1", timeout=20)
    child.expect(pexpect.EOF)
    assert "set" in child.before
