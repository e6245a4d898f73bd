"""The key feed alone (harness/machine/key_feed.py), on a pty whose reader is a
stand-in process that never reads: what waits where, ^C, ^E, the boot."""
import os
import signal
import subprocess
import sys
import termios
import time
import tty

import pytest

from harness.machine.console_watch import Leave, LineWatcher
from harness.machine.key_feed import WINDOW, KeyFeed, shown


@pytest.fixture
def feed():
    """A KeyFeed on a pty; the process on its slave ignores SIGUSR1 and reads nothing."""
    master, slave = os.openpty()
    tty.setraw(slave)                                    # as SIMH keeps it while running
    reader = subprocess.Popen([sys.executable, "-c", "import signal, time; signal.signal("
                               "signal.SIGUSR1, signal.SIG_IGN); time.sleep(60)"],
                              stdin=slave)
    name = os.ttyname(slave)
    os.close(slave)
    deadline = time.monotonic() + 10                     # its stdin is the pty once it runs
    while os.readlink(f"/proc/{reader.pid}/fd/0") != name and time.monotonic() < deadline:
        time.sleep(0.01)
    keys = KeyFeed(master, reader.pid, limit=10000)
    yield keys
    reader.send_signal(signal.SIGKILL)
    reader.wait()
    os.close(master)


def in_pty_soon(feed, n):
    """The kernel moves a pty's input to the reader's side a moment after the
    write: FIONREAD gets there soon."""
    deadline = time.monotonic() + 5
    while feed.in_pty() != n and time.monotonic() < deadline:
        time.sleep(0.005)
    return feed.in_pty() == n


def test_keys_wait_for_the_boot_then_go_a_window_at_a_time(feed):
    watcher = LineWatcher()
    text = b"".join(b"%d DROP\r" % n for n in range(100))
    feed.typed(text, watcher)
    assert feed.pump(watcher) == 0 and feed.waiting() == len(text)   # not booted
    feed.output(b"blocks 0-10239.\r\n ok\r\n")
    assert feed.pump(watcher) == WINDOW
    assert in_pty_soon(feed, WINDOW) and feed.waiting() == len(text)
    assert feed.pump(watcher) == 0                       # the window is full: no blocking
    assert feed.room() == 10000 - (len(text) - WINDOW)


def test_ctrl_c_drops_what_waits_here_and_in_the_pty(feed):
    watcher = LineWatcher()
    feed.output(b" ok\r\n")
    feed.typed(b"x" * 1000, watcher)
    feed.pump(watcher)
    notes = feed.typed(b"\x03", watcher)
    assert notes == ["^C: 1000 characters typed or pasted and not yet read by the machine "
                     "were dropped"]
    assert feed.waiting() == 0


def test_ctrl_e_takes_the_pty_back_and_sends_only_itself(feed):
    watcher = LineWatcher()
    feed.output(b" ok\r\n")
    text = bytes(range(65, 91)) * 20
    feed.typed(text, watcher)
    feed.pump(watcher)
    feed.typed(b"\x05", watcher)
    assert bytes(feed.queue) == text                     # whole, in order, nothing doubled
    assert in_pty_soon(feed, 1)                          # only ^E is in the pty
    assert feed.pump(watcher) == 0                       # held until sim> comes and goes


def test_keys_typed_after_cont_wait_until_simh_gives_the_machine_back(feed):
    """SIMH empties the pty as CONT gives the FORTH its keys back: what is typed
    behind CONT waits until the pty has left sim>'s line editing."""
    watcher = LineWatcher()
    feed.output(b" ok\r\n")
    mode = termios.tcgetattr(feed.fd)
    mode[3] |= termios.ICANON                            # sim> reads lines
    termios.tcsetattr(feed.fd, termios.TCSANOW, mode)
    watcher.output(b"sim> ")
    feed.typed(b"cont\r1 .\r", watcher)
    assert not watcher.at_simh and bytes(feed.queue) == b"1 .\r"
    assert feed.pump(watcher) == 0                       # CONT not yet taken
    tty.setraw(feed.fd)                                  # as SIMH runs the machine
    assert feed.pump(watcher) == 4 and not feed.queue


def test_a_way_out_in_a_paste_stops_it_there(feed):
    watcher = LineWatcher()
    feed.output(b" ok\r\n")
    feed.typed(b"1 .\rBYE\r2 .\r", watcher)
    with pytest.raises(Leave) as way:
        feed.pump(watcher)
    assert way.value.typed == b"1 .\rBYE" and feed.discard() == 4


def test_flow_control_characters_never_reach_the_screen():
    assert shown(b"ok\x13\r\n\x11") == b"ok\r\n"
