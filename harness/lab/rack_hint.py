"""A hint at the console when a move waits on an amplifier rack that is off (pure logic).

The lab boots with the rack off, as `make run` does (nothing drifts while the
blocks load). A move typed before the rack is switched on sets Command.Status
(block 1009, Abs.Move.Single) and the servo commands the DACs, but no axis moves,
so Stop? (block 1003) never clears it and Move.Complete? waits for ever with
nothing said. The blocks stay as printed; the lab notices instead: a move still
executing after HINT_AFTER_S simulated seconds with the rack off gets one line.
"""
HINT_AFTER_S = 2.0
HINT = ("[lab] The amplifier rack is OFF, so the axes cannot move: this move never "
        "completes (Move.Complete? waits for ever). ^C stops a wait; then switch the "
        "amplifiers on (the page's button, or ^E SET PLANT POWER=ON, then CONT).")


class RackHint:
    def __init__(self):
        self.since = None              # simulated time the wait began
        self.said = False

    def update(self, power, time, servo):
        """The hint to print now, or None: once per wait."""
        executing = any(servo.get("Command.Status") or ())
        if power != "off" or not executing:
            self.since, self.said = None, False
            return None
        if self.since is None:
            self.since = time
        if not self.said and time - self.since >= HINT_AFTER_S:
            self.said = True
            return HINT
        return None
