"""The page's keystrokes on their way to the simulator's console (pure logic).

While the FORTH has the keyboard, keys go through as typed (the FORTH's ACCEPT
edits its own line). While SIMH has its sim> prompt, or is about to have it (a
^E was sent), the guard edits the line itself (backspace, ^U, ^W; echoed to the
page only) and, at Enter, hands SIMH the whole line only when sim_commands
allows it; otherwise the page gets one line saying why and a fresh prompt.

What SIMH reads is then exactly what was checked, whatever the timing: the
simulator's terminal is set (prompt_termios) so that at sim> only a line feed
ends a line (no CR conversion) and no key raises a signal, quotes the next key
or stops output. Keys meant for the FORTH never carry a line feed (the guard
turns one into the CR the FORTH's ACCEPT also takes), so if SIMH stops by itself
(a breakpoint, STEP's end) while keys are on their way, they wait in SIMH's line
unfinished, and the guard's checked line starts with two ^U that erase them.

keys() returns actions: ("pty", bytes) for the simulator (through the key feed,
whose watcher sees BYE and ^D), ("page", bytes) for the page's terminal only. ^C
and ^D at sim> raise the LineWatcher's Leave with `actions` (what still goes out
before it): the lab then leaves as the console does, FLUSHing the FORTH's blocks
first. SIMH's QUIT, EXIT and BYE are allowed: SIMH FLUSHes first itself
(pdp11-devices/simh/leave_check.c).
"""
import termios

from harness.lab.sim_commands import MAY_RUN_TEXT, refusal
from harness.machine.console_watch import CTRL_C, CTRL_D, CTRL_E, CTRL_U, Leave

CR, LF, ESC, TAB, BS, DEL, CTRL_W = 13, 10, 27, 9, 8, 127, 23
KILL = bytes([CTRL_U, CTRL_U])   # erases what reached SIMH's line unchecked (even after a quoting key)
ERASE = b"\b \b"


def prompt_termios(fd=0):
    """The simulator's terminal as SIMH finds it at start, and so as it restores it
    at each sim> (sim_console.c keeps these as its command mode; its run mode
    sets its own keys): only LF ends a line, and ^C, ^\\, ^Z, ^D, ^V, ^O, ^S are
    ordinary characters there. Called in the child before SIMH starts."""
    mode = termios.tcgetattr(fd)
    mode[0] &= ~(termios.ICRNL | termios.INLCR | termios.IGNCR | termios.IXON)
    for key in (termios.VINTR, termios.VQUIT, termios.VSUSP, termios.VEOF, termios.VEOL,
                termios.VEOL2, termios.VLNEXT, termios.VDISCARD):
        mode[6][key] = b"\0"                       # _POSIX_VDISABLE on Linux
    termios.tcsetattr(fd, termios.TCSANOW, mode)


class SimPromptGuard:
    """Between the page's keys and the simulator. `watcher` is the lab's
    LineWatcher: it follows the output (is sim> up?) and the ways out."""

    def __init__(self, watcher):
        self.watcher = watcher
        self.line = bytearray()          # the sim> line being typed
        self.stopping = False            # a ^E went to SIMH: its prompt is coming
        self.waiting = bytearray()       # keys typed after the ^E, before the prompt
        self.escape = None               # inside an escape sequence (arrow keys)
        self.after_cr = False            # the FORTH's last key was CR (skip its LF)
        self.sent = False                # keys() stopped after a line sent to SIMH

    @property
    def at_prompt(self):
        return self.watcher.at_simh

    def keys(self, data):
        """The actions for `data` typed on the page (b"" when the prompt just came:
        the keys that waited for it). It stops after a checked line went to SIMH:
        the caller writes it (its CONT gives the machine back), then calls again
        while more() says keys wait."""
        out = []
        data, self.waiting = bytes(self.waiting) + data, bytearray()
        self.sent = False
        try:
            for i, byte in enumerate(data):
                if self.stopping and not self.at_prompt:
                    self.waiting += data[i:]     # SIMH is stopping: the line waits for sim>
                    break
                if self._escape(byte):
                    continue
                if self.at_prompt:
                    self.stopping = False
                    if self._prompt_key(byte, out):
                        self.waiting += data[i + 1:]
                        self.sent = True
                        break
                else:
                    self._forth_key(byte, out)
        except Leave as way:
            way.actions = out
            raise
        return _merged(out)

    def more(self):
        """Keys wait behind a line just sent to SIMH."""
        return self.sent and bool(self.waiting)

    def _escape(self, byte):
        """Escape sequences (arrow and function keys) are dropped: neither the
        FORTH's line nor SIMH's prompt can use them, and their letters would land
        in the line as text."""
        if self.escape is None:
            if byte != ESC:
                return False
            self.escape = b""
            return True
        if self.escape == b"":
            if byte not in b"[O":
                self.escape = None               # a lone ESC: dropped, the key goes on
                return False
            self.escape = bytes([byte])
        elif not 0x40 <= byte <= 0x7E:
            pass                                 # a CSI parameter: more to come
        else:
            self.escape = None                   # final byte (or ESC + one key)
        return True

    def _forth_key(self, byte, out):
        if byte == LF and self.after_cr:
            self.after_cr = False                # CR LF is one line end
            return
        self.after_cr = byte == CR
        if byte == LF:
            byte = CR                            # ACCEPT takes either; SIMH's line only LF
        out.append(("pty", bytes([byte])))      # the key feed's watcher sees BYE, ^D
        if byte == CTRL_E:
            self.stopping = True

    def _prompt_key(self, byte, out):
        if byte == CTRL_D:
            raise Leave("^D")
        if byte == CTRL_C:
            raise Leave("^C at SIMH's prompt")
        if byte in (CR, LF):
            return self._line_done(out)
        elif byte in (BS, DEL):
            self._erase(1, out)
        elif byte in (CTRL_U, CTRL_E):
            self._erase(len(self.line), out)
        elif byte == CTRL_W:
            kept = bytes(self.line).rstrip(b" ")
            kept = kept[:kept.rfind(b" ") + 1]
            self._erase(len(self.line) - len(kept), out)
        elif byte == TAB or byte >= 32:
            byte = 32 if byte == TAB else byte
            self.line.append(byte)
            out.append(("page", bytes([byte])))

    def _erase(self, count, out):
        count = min(count, len(self.line))
        if count:
            del self.line[-count:]
            out.append(("page", ERASE * count))

    def _line_done(self, out):
        typed, self.line = bytes(self.line), bytearray()
        out.append(("page", ERASE * len(typed)))          # SIMH's own echo replaces it
        text = typed.decode("latin-1")
        why = refusal(text)
        if why:
            out.append(("page", typed + f"\r\nlab: refused: {why}. From the page SIMH "
                        f"runs {MAY_RUN_TEXT}.\r\nsim> ".encode("latin-1")))
            return False
        out.append(("pty", KILL + typed + b"\n"))  # its watcher: CONT gives the FORTH the keys
        return True


def _merged(actions):
    """Neighbouring actions of one kind joined: one write per destination."""
    merged = []
    for kind, data in actions:
        if merged and merged[-1][0] == kind:
            merged[-1] = (kind, merged[-1][1] + data)
        else:
            merged.append((kind, data))
    return merged
