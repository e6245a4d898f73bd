"""KEY's wait (forth/kernel/prims.fs): it WAITs for the receive interrupt with the
ring empty, and polls the DL11 itself while the priority masks that interrupt, so
`Disable.Interrupts` typed at the terminal (block 1008) leaves the console usable.
Lines here arrive through the DL11 (harness/machine/machine.py types into the pty)."""

import pytest

from harness.machine.build import KERNEL, PDP11 as SIMULATOR, PRISTINE_DISK, fresh_disk
from harness.machine.machine import Machine



@pytest.fixture
def appendix(tmp_path):
    for need in (KERNEL, SIMULATOR, PRISTINE_DISK):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    with Machine(disk=fresh_disk(tmp_path, "rl0.dsk")) as m:
        m.send("1000 LOAD")
        yield m


def priority(m):
    """The processor priority, read by the FORTH itself (MFPS)."""
    m.send("CODE PS@ ( -- ps ) R0 MFPS, S -) R0 MOV, NEXT,")
    return int(m.send("PS@ 5 RSHIFT 7 AND .").split()[0])


def test_key_waits_for_a_typed_character():
    with Machine() as m:
        m.child.send(": K2 ( -- c1 c2 ) KEY KEY ; K2 . .\r")
        m.child.send("AB")                          # after the line: KEY waits for them
        m.child.expect(r"66 65  ok\r\n")


def test_disable_interrupts_at_the_terminal_leaves_the_console_listening(appendix):
    m = appendix
    assert priority(m) == 0
    m.send("Disable.Interrupts")
    assert priority(m) == 7                         # the DL11 cannot interrupt now
    assert m.send("6 7 * .") == "42 "               # yet the line was read (polled)
    m.child.send("KEY .\rZ")
    m.child.expect(r"90  ok\r\n")
    m.send("Restore.Processor")
    assert priority(m) == 0
    assert m.send("2 3 + .") == "5 "
