"""The keys on their way to the simulator: held by the harness, written into SIMH's
pty a window at a time, so a paste of any size arrives whole (docs/console.md,
"A paste").

    feed = KeyFeed(child.child_fd, child.pid)
    feed.typed(data, watcher)      # what the user typed (^C and ^E act at once)
    feed.pump(watcher)             # call often: writes what the window allows
    feed.waiting()                 # characters not yet read by the simulator

The FORTH's receive interrupt sends XOFF when its ring fills and the terminal
side (pdp11-devices/console_pacing.c) then stops reading the pty; the pty fills
up to WINDOW characters and the rest waits here, in `queue`, for as long as it
takes. No write ever blocks: the caller's loop keeps reading the simulator's
output (else the simulator would stop on a full pty and never drain its input).

^C (not at sim>) drops what is still waiting here and in the pty, says how much,
and has the terminal side put ^C into the DL11 at once (SIGUSR1): the FORTH then
drops its ring and says how much. ^E: what the pty still holds is taken back
(read out of it) into the queue first (SIMH flushes the pty when it stops), then
^E goes in; the queue waits while SIMH's sim> is up and goes on after CONT, once
SIMH has taken the machine back (it empties the pty then: the pty's mode changes from
sim>'s line editing to the machine's raw keys). Keys typed at sim> go straight in, a
line at a time: what follows a CONT waits for the machine in the queue.
The simulator is stopped (SIGSTOP) for the instant the pty is emptied, so no
character is read meanwhile.

The watcher (harness/machine/console_watch.py) sees each byte when it is
written, so a way out inside a paste (BYE, ^D) counts where it stands.
"""
import contextlib
import fcntl
import os
import signal
import struct
import termios
import time

from harness.machine.console_watch import Leave
from harness.machine.pty_child import CONT_WAIT_S, line_editing

WINDOW = 256                 # characters the pty may hold: taken back at ^E, dropped at ^C
# After CONT the queue waits until SIMH has put the pty out of sim>'s line editing,
# at most pty_child.CONT_WAIT_S; where sim>'s mode could not be seen, RESUME_AFTER_CONT_S.
RESUME_AFTER_CONT_S = 0.3
STOP_KEY_WAIT_S = 2.0        # at most this long waiting for sim> after ^E
CTRL_C, CTRL_E, CTRL_U = 3, 5, 21


def shown(data):
    """The machine's output as the screen gets it: XON and XOFF are the terminal's."""
    return data.translate(None, b"\x11\x13")


def process_state(pid):
    """The state letter of process `pid` (R, S, T, Z ...; /proc's), None when it is gone."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return None


@contextlib.contextmanager
def frozen(pid):
    """The simulator stopped (SIGSTOP) for the block's duration."""
    try:
        os.kill(pid, signal.SIGSTOP)
    except ProcessLookupError:
        yield
        return
    try:
        deadline = time.monotonic() + 1
        while process_state(pid) not in ("T", "t", "Z", None) and time.monotonic() < deadline:
            time.sleep(0.0002)
        yield
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGCONT)


class KeyFeed:
    def __init__(self, fd, pid, limit=None):
        """fd: the pty's master; pid: the simulator; limit: the most characters
        the queue takes (None: no bound; room() says what is left)."""
        self.fd, self.pid, self.limit = fd, pid, limit
        self.queue = bytearray()
        self.stopping = None          # monotonic deadline while ^E waits for sim>
        self.was_simh = False
        self.simh_edits = False       # sim> was seen reading the pty a line at a time
        self.resume_at = 0.0
        self.abandoned = 0            # characters after a way out, never typed
        self.booted = False           # SIMH empties the pty as it starts the machine (GO):
        self._tail = b""              # keys wait for the FORTH's first prompt
        try:
            self.slave = os.readlink(f"/proc/{pid}/fd/0")
        except OSError:
            self.slave = None

    # ---- what is where ------------------------------------------------------------
    def in_pty(self):
        """Characters written into the pty the simulator has not read yet."""
        if not self.slave:
            return 0
        try:
            fd = os.open(self.slave, os.O_RDONLY | os.O_NOCTTY | os.O_NONBLOCK)
        except OSError:
            return 0
        try:
            return struct.unpack("i", fcntl.ioctl(fd, termios.FIONREAD, b"\0" * 4))[0]
        except OSError:
            return 0
        finally:
            os.close(fd)

    def _take_pty(self):
        """What the simulator has not read from the pty, taken out of it (the
        simulator frozen): the exact bytes. (A read also brings across what the
        kernel had not yet moved to the reader's side, which FIONREAD misses.)"""
        if not self.slave:
            return b""
        taken = bytearray()
        try:
            fd = os.open(self.slave, os.O_RDONLY | os.O_NOCTTY | os.O_NONBLOCK)
        except OSError:
            return b""
        try:
            while True:
                data = os.read(fd, 1 << 16)
                if not data:
                    break
                taken += data
        except OSError:
            pass                                  # EAGAIN: nothing more
        finally:
            os.close(fd)
        return bytes(taken)

    def _at_simh(self):
        self.stopping, self.was_simh = None, True
        self.simh_edits = line_editing(self.fd) is True

    def waiting(self):
        return len(self.queue) + self.in_pty()

    def room(self):
        return None if self.limit is None else max(0, self.limit - len(self.queue))

    # ---- the user's keys ----------------------------------------------------------
    def typed(self, data, watcher):
        """Keys from the user. Returns notes for the user (a ^C that dropped
        input says how much). May raise Leave (a way out typed at sim>)."""
        notes = []
        start = 0
        for i, byte in enumerate(data):
            if byte not in (CTRL_C, CTRL_E) or watcher.at_simh:
                continue
            self._put(data[start:i], watcher)
            start = i + 1
            if byte == CTRL_C:
                watcher.line.clear()              # the FORTH drops the line too
                dropped = self.interrupt()
                if dropped:
                    notes.append(f"^C: {dropped} characters typed or pasted and not yet "
                                 "read by the machine were dropped")
            else:
                self.stop_key(watcher)
        self._put(data[start:], watcher)
        return notes

    def _put(self, data, watcher):
        while data and watcher.at_simh:          # to SIMH's prompt, a line at a time ...
            self._at_simh()
            ends = [i for i in (data.find(b"\r"), data.find(b"\n")) if i >= 0]
            line = data[:min(ends) + 1] if ends else data
            self._write(line, watcher)
            data = data[len(line):]
        self.queue += data                       # ... what follows a CONT waits for the machine

    def interrupt(self):
        """^C: drop what waits here and in the pty; ^C into the DL11 at once."""
        with frozen(self.pid):
            dropped = len(self.queue) + len(self._take_pty())
            self.queue.clear()
        with contextlib.suppress(ProcessLookupError):
            os.kill(self.pid, signal.SIGUSR1)
        return dropped

    def discard(self):
        """Leaving: the queue is dropped (what is in the pty is still read, ahead
        of the FLUSH); how many characters, with those after a way out."""
        dropped = len(self.queue) + self.abandoned
        self.queue.clear()
        self.abandoned = 0
        return dropped

    def stop_key(self, watcher):
        """^E: the pty's unread characters back into the queue, then ^E."""
        with frozen(self.pid):
            self.queue[:0] = self._take_pty()
            self._write(bytes([CTRL_E]), watcher)
        self.stopping = time.monotonic() + STOP_KEY_WAIT_S

    # ---- into the pty ---------------------------------------------------------------
    def output(self, data):
        """Follow the machine's output: until the FORTH's first ` ok` the machine
        has not started, and what was typed waits."""
        if not self.booted:
            self._tail = (self._tail + data)[-8:]
            self.booted = b" ok\r\n" in self._tail

    def held(self, watcher):
        """Whether the queue must wait (not booted yet; sim> is up, or coming, or
        just left)."""
        if not self.booted:
            return True
        now = time.monotonic()
        if watcher.at_simh:
            self._at_simh()
            return True
        if self.was_simh:                       # CONT: SIMH flushes the pty as it runs
            self.was_simh = False
            self.resume_at = now + (CONT_WAIT_S if self.simh_edits else RESUME_AFTER_CONT_S)
        if self.stopping is not None:
            if now < self.stopping:
                return True
            self.stopping = None
        if now < self.resume_at:
            if not self.simh_edits or line_editing(self.fd):
                return True
            self.resume_at = 0.0                # the machine runs: the pty is its own
        return False

    def pump(self, watcher):
        """Write what the window allows; the number of bytes written. A way out
        among them raises Leave (the rest of the queue is abandoned)."""
        if self.held(watcher) or not self.queue:     # held() follows sim> every time
            return 0
        room = WINDOW - self.in_pty()
        if room <= 0:
            return 0
        chunk = bytes(self.queue[:room])
        try:
            self._write(chunk, watcher)
        except Leave as way:
            self.abandoned = len(self.queue) - len(way.typed) - 1
            self.queue.clear()
            raise
        del self.queue[:len(chunk)]
        return len(chunk)

    def _write(self, data, watcher):
        watcher.feed(data)                      # raises Leave before anything is written
        view = memoryview(data)
        while view:
            try:
                n = os.write(self.fd, view)
            except BlockingIOError:
                time.sleep(0.001)               # the pty is full: only a few bytes, rarely
                continue
            except OSError:
                return                          # the simulator has gone: its end is read
            view = view[n:]
