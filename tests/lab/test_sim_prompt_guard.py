"""The guard's keystroke logic alone (harness/lab/sim_prompt_guard.py)."""
import pytest

from harness.lab.sim_commands import refusal
from harness.lab.sim_prompt_guard import KILL, SimPromptGuard
from harness.machine.console_watch import Leave, LineWatcher


def guard(at_prompt=False):
    watcher = LineWatcher()
    if at_prompt:
        watcher.output(b"sim> ")
    return SimPromptGuard(watcher)


def to_pty(actions):
    return b"".join(data for kind, data in actions if kind == "pty")


def test_forth_keys_never_carry_a_line_feed():
    g = guard()
    assert to_pty(g.keys(b"1 2 + .\r\n3 .\n")) == b"1 2 + .\r3 .\r"
    assert to_pty(g.keys(b"\n")) == b"\r"            # a lone LF after a lone LF's CR


def test_keys_after_ctrl_e_wait_for_the_prompt_and_are_checked():
    g = guard()
    assert to_pty(g.keys(b"\x05! id\r")) == b"\x05"
    g.watcher.output(b"\r\nSimulation stopped, PC: 001234\r\nsim> ")
    actions = g.keys(b"")
    assert to_pty(actions) == b"" and b"lab: refused: ! runs" in actions[-1][1]


def test_an_allowed_line_goes_whole_after_the_kill_and_the_rest_waits():
    g = guard(at_prompt=True)
    assert to_pty(g.keys(b"sh")) == b""
    assert to_pty(g.keys(b"ow plantX\x7f\r")) == KILL + b"show plant\n"
    assert to_pty(g.keys(b"c\r1 2 +\r")) == KILL + b"c\n" and g.more()
    g.watcher.feed(KILL + b"c\n")                   # the key feed writes it: the FORTH runs
    assert to_pty(g.keys(b"")) == b"1 2 +\r" and not g.more()


def test_ways_out_at_the_prompt():
    with pytest.raises(Leave) as way:                # ^C would kill SIMH: the lab leaves
        guard(at_prompt=True).keys(b"\x03")
    assert "^C" in way.value.how
    for line in (b"qu\r", b"exit\r"):             # SIMH's own: it FLUSHes first
        assert to_pty(guard(at_prompt=True).keys(line)) == KILL + line[:-1] + b"\n"


@pytest.mark.parametrize("line", ["SHOW PLANT", "sh plant", "e pc", "d r0 5", "s", "step 100",
                                  "c", "cont", "br 2000", "nobr", "set cpu history=100",
                                  "set -a plant power=on", "set clk rate=300000",
                                  "se lab speed=0", "", "; comment", "help"])
def test_the_pages_commands(line):
    assert refusal(line) is None


@pytest.mark.parametrize("line", ["!", "! ls", "a lpt x", "det rl0", "sa f", "rest f", "get f",
                                  "lo f", "du f", "do f", "set console telnet=1", "set br 100",
                                  "set throttle 50%", "set cpu 64k", "set cpu idle",
                                  "set cpu hist=5 nommu", "set plant debug", "set rl0 locked",
                                  "sh @f cpu", "e @f pc", "d rl 0 0", "dep rl1 0 0",
                                  "br 100;sh cpu", "ru", "go 0", "b", "reset", "as cpu x",
                                  "ie pc", "id pc", "show caf\xe9"])
def test_refused_commands(line):
    assert refusal(line)
