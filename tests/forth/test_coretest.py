"""gforth's packaged Hayes core test, fed line by line through the console.

The test file is read from the installed gforth package at test time (never
copied here); tests/forth/tester.fs is this project's { -> } harness."""
from pathlib import Path

import pytest

from harness.machine import Machine

CORETEST = Path("/usr/share/gforth/0.7.3/test/coretest.fs")
TESTER = Path(__file__).with_name("tester.fs")


def test_hayes_core_test():
    if not CORETEST.exists():
        pytest.fail(f"{CORETEST} missing: install gforth (bash mk/apt-need.sh gforth)")
    with Machine() as m:
        for line in TESTER.read_text().splitlines():
            m.send(line)
        failed_lines, errors = [], []
        for n, line in enumerate(CORETEST.read_text(encoding="latin-1").splitlines(), 1):
            r = m.reply(line)
            if not r.ok:
                errors.append(f"{n}: {line.strip()} -> {r.error}")
            if "TEST FAILED" in r.output:
                failed_lines.append(f"{n}: {r.output.strip()}")
        tests = int(m.send("#TESTS @ .").split()[0])
        failed = int(m.send("#FAILED @ .").split()[0])
    print(f"\nHayes core test: {tests} tests, {failed} failed, "
          f"{len(errors)} lines with errors")
    assert not errors, "\n".join(errors[:20])
    assert failed == 0 and not failed_lines, "\n".join(failed_lines[:20])
    assert tests > 300
