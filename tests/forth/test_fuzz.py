"""The short console fuzz (make fuzz runs 10 000 lines): 2 000 seeded random
lines of issue 8's kinds end at the prompt every one, and the blocks still
load and move the robot afterwards; then 4 rounds of a second simulator on the
fuzz's image (refused read-write, harmless read-only)."""
from harness.fuzz.console_fuzz import fuzz
from harness.fuzz.lines import LineMaker


def test_lines_are_seeded():
    first = [LineMaker(5).line() for _ in range(3)]
    assert first == [LineMaker(5).line() for _ in range(3)]
    other = LineMaker(6)
    assert first != [other.line() for _ in range(3)]


def test_two_thousand_random_lines():
    report = fuzz(2000, seed=8, writer_rounds=4)
    print(report.text())
    assert (report.halts, report.hangs, report.reboots) == ([], [], []), report.text()
    assert sum(report.errors.values()) > 1000          # the lines did provoke errors
    assert report.move_works, report.text()
    assert report.two_writers == [], report.text()     # two simulators on one image
