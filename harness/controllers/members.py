"""One of the five machines driven by a scripted run: a ScriptedMachine (stops at
its FORTH prompt, lines typed at exact instruction counts) that is a member of
the lock-step (its SIMH settings from coordinator.member_settings).

Why the five stay deterministic however the host schedules them: a member stops
only at instruction counts of its own (its prompt, a STEP's end); while it is
stopped the others wait at the next quantum boundary (their LOCKSTEP device
blocks there), so no member's simulated time runs ahead, and what crosses
between machines (the plant, the links) crosses only at boundaries. A member
that needs no more input runs free (no stop at its prompt) until the session
ends: run_free.
"""
from pathlib import Path

from harness.controllers.coordinator import CONTROLLERS, member_settings
from harness.machine.build import KERNEL, PDP11
from harness.machine.scripted_machine import ScriptedMachine, feed_commands

# what an 11/03 prints when the session ends under it (pdp11-devices/simh/lockstep_dev.c)
SESSION_OVER = ("LOCKSTEP: the 11/23 has left", "LOCKSTEP: the coordinator is gone")


class MemberMachine(ScriptedMachine):
    def __init__(self, member, socket, disk, cwd, kernel=KERNEL, line_limit=60.0,
                 wall_timeout=300, simulator=PDP11):
        """Boots `member` (x, y, z, t or main) from `disk` (relative to `cwd`) to its
        first prompt; returns only once every member runs (the first boundary)."""
        self.member = member
        super().__init__(disk, cwd=cwd, kernel=kernel, kernel_map=Path(kernel).with_suffix(".map"),
                         settings=member_settings(member, socket), line_limit=line_limit,
                         wall_timeout=wall_timeout, simulator=simulator)

    @property
    def pid(self):
        return self.child.pid

    def run_free(self, text=None, timeout=3600):
        """Type `text` (if any) as the next line, then run with no stop at the prompt
        until the session ends (or the machine stops otherwise); the Answer."""
        if text is not None:
            for command in feed_commands(self.sym, text, self._ring_head()):
                self.simh(command)
        self.simh("deposit cue pc 0")
        self.child.timeout = timeout
        return self._run("cont", "the free run")


def session_over(answer):
    return any(s in answer.output for s in SESSION_OVER)
