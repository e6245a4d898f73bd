"""gforth's packaged Hayes core test, fed line by line through the console,
typed ahead a few lines at a time.

The test file is read from the installed gforth package at test time (never
copied here); tests/forth/tester.fs is this project's { -> } harness."""
from collections import deque
from pathlib import Path

import pytest

from harness.machine.machine import Machine
from tests.forth.suite import SuiteResult, assert_passed, feed, load_tester, totals

CORETEST = Path("/usr/share/gforth/0.7.3/test/coretest.fs")
AHEAD = 20          # lines typed before their answers are read: some 600 characters


class TypedAhead:
    """The machine with the lines typed AHEAD at a time, as a user pastes them:
    the FORTH's ring and its XON/XOFF keep them (test_language.py's paste tests),
    and an error leaves the lines after it in the ring. A round trip a line cost
    more host CPU (the simulator's idle steps and pexpect's) than the FORTH's
    work. reply(line) is Machine.reply's answer."""

    def __init__(self, machine, lines):
        self.machine, self.lines, self.typed = machine, deque(lines), deque()

    def reply(self, line):
        if not self.typed:
            for _ in range(min(AHEAD, len(self.lines))):
                self.typed.append(self.lines.popleft())
            self.machine.child.send("".join(f"{typed}\r" for typed in self.typed))
        assert self.typed.popleft() == line, "the lines are answered in the order typed"
        return self.machine.answer(line)


def test_hayes_core_test():
    if not CORETEST.exists():
        pytest.fail(f"{CORETEST} missing: install gforth (bash mk/apt-need.sh gforth)")
    result = SuiteResult()
    with Machine() as m:
        load_tester(m)
        text = CORETEST.read_text(encoding="latin-1").splitlines()
        feed(TypedAhead(m, text), "coretest.fs", enumerate(text, 1), result)
        totals(m, result)
    assert_passed(result, "Hayes core test", at_least=300)
