"""The short console fuzz (make fuzz runs 10 000 lines): 2 000 seeded random
lines of issue 8's kinds end at the prompt every one, and the blocks still
load and move the robot afterwards."""
from harness.fuzz.console_fuzz import fuzz
from harness.fuzz.lines import LineMaker


def test_lines_are_seeded():
    first = [LineMaker(5).line() for _ in range(3)]
    assert first == [LineMaker(5).line() for _ in range(3)]
    other = LineMaker(6)
    assert first != [other.line() for _ in range(3)]


def test_two_thousand_random_lines():
    report = fuzz(2000, seed=8)
    print(report.text())
    assert (report.halts, report.hangs, report.reboots) == ([], [], []), report.text()
    assert sum(report.errors.values()) > 1000          # the lines did provoke errors
    assert report.move_works, report.text()
