"""What the console's user is doing, from the keystrokes and the simulator's output.

The harness lets the user type straight to the FORTH or, after ^E, to SIMH's sim>
prompt, and watches for the ways out that SIMH itself does not guard, so that
the FORTH's UPDATEd block buffers are written before the simulator ends:

  BYE on a line of its own, or ^D            anywhere
  ^C                                         at sim> (SIMH would die of the SIGINT)
  the FORTH's BYE word run within a line   seen in the output: SIMH's report of
                                             the HALT at (BYE) (halt_marker)

Each raises Leave before the simulator sees it. SIMH's own QUIT, EXIT and BYE at
sim> are not watched here: however they are typed, edited or read from a DO file,
the simulator FLUSHes the FORTH's blocks first (pdp11-devices/simh/leave_check.c),
which a watcher of keystrokes could not promise (the terminal edits the line). Whether SIMH has the prompt is
followed from the output (a chunk ending in "sim> ") and from the commands typed
there (RUN, GO, CONT, BOOT and STEP give the machine back to the FORTH). Pure
logic: bytes in, Leave out.
"""
from harness.machine.simh_command import RUNS, simh_command

CTRL_C, CTRL_D, CTRL_E, CTRL_U = 3, 4, 5, 21
SIM_PROMPT = b"sim> "


class Leave(Exception):
    """The user asked to leave; `how` names the way (for the report). `typed` is
    what came in the same read before the way out (a line typed ahead of BYE, the
    letters of BYE itself): the simulator must still get it."""

    def __init__(self, how, typed=b""):
        super().__init__(how)
        self.how, self.typed = how, typed


class LineWatcher:
    """Follows what the user types, line by line, and whether SIMH is reading it."""

    def __init__(self, halt_marker=None):
        """halt_marker: what SIMH prints when the FORTH's BYE word halts
        (b"HALT instruction, PC: <(BYE)+2>"), None when the kernel has no BYE."""
        self.line = bytearray()
        self.at_simh = False
        self.halt_marker = halt_marker
        self._tail = b""
        self._keep = max(len(SIM_PROMPT), 2 * len(halt_marker or b""))

    def output(self, data):
        """Follow the simulator's output (interact's output_filter); unchanged,
        or Leave when it reports the halt of the BYE word."""
        self._tail = (self._tail + data)[-self._keep:]
        if self._tail.endswith(SIM_PROMPT):
            self.at_simh = True
        if self.halt_marker and self.halt_marker in self._tail:
            self._tail = b""
            raise Leave("the BYE word")
        return data

    def feed(self, data):
        """Raise Leave when `data` holds a way out; else give it back unchanged."""
        for i, byte in enumerate(data):
            try:
                self._key(byte)
            except Leave as way:
                way.typed = bytes(data[:i])
                raise
        return data

    def _key(self, byte):
        if byte == CTRL_D:
            raise Leave("^D")
        if byte == CTRL_C and self.at_simh:
            raise Leave("^C at SIMH's prompt")
        if byte in (13, 10):
            typed, self.line = self.line.decode("latin-1"), bytearray()
            self._line_typed(typed)
        elif byte in (8, 127):
            del self.line[-1:]
        elif byte in (CTRL_U, CTRL_E):
            self.line.clear()
        elif byte >= 32:
            self.line.append(byte)

    def _line_typed(self, typed):
        if typed.strip().upper() == "BYE":
            raise Leave("BYE")
        if not self.at_simh:
            return
        if simh_command(typed) in RUNS:
            self.at_simh = False
