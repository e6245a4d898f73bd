"""Feeding a test file written for the { ... -> ... } harness (tests/forth/tester.fs)
through the console, line by line, and counting what it reports."""
from dataclasses import dataclass, field
from pathlib import Path

TESTER = Path(__file__).with_name("tester.fs")


@dataclass
class SuiteResult:
    tests: int = 0
    failed: int = 0
    errors: list = field(default_factory=list)        # "where: line -> error"
    failed_lines: list = field(default_factory=list)  # "where: TEST FAILED ..."


def load_tester(machine, *extra):
    """tester.fs, then any extra lines (stand-ins a suite expects)."""
    for line in TESTER.read_text().splitlines() + list(extra):
        machine.send(line)


def feed(machine, name, lines, result):
    """Type the lines; note the ones that fail and the failed tests."""
    for n, line in lines:
        r = machine.reply(line)
        if not r.ok:
            result.errors.append(f"{name}:{n}: {line.strip()} -> {r.error}")
        if "TEST FAILED" in r.output:
            result.failed_lines.append(f"{name}:{n}: {r.output.strip()}")


def totals(machine, result):
    """#TESTS and #FAILED into result (the suites may leave BASE at 16)."""
    machine.send("DECIMAL")
    result.tests = int(machine.send("#TESTS @ .").split()[0])
    result.failed = int(machine.send("#FAILED @ .").split()[0])
    return result


def assert_passed(result, label, note="", at_least=1):
    """Print the totals; fail on any error, failed test, or too few tests."""
    print(f"\n{label}: {result.tests} tests, {result.failed} failed, "
          f"{len(result.errors)} lines with errors{note}")
    assert not result.errors, "\n".join(result.errors[:20])
    assert result.failed == 0 and not result.failed_lines, "\n".join(result.failed_lines[:20])
    assert result.tests >= at_least
