"""gforth's packaged Hayes core test, fed line by line through the console.

The test file is read from the installed gforth package at test time (never
copied here); tests/forth/tester.fs is this project's { -> } harness."""
from pathlib import Path

import pytest

from harness.machine.machine import Machine
from tests.forth.suite import SuiteResult, assert_passed, feed, load_tester, totals

CORETEST = Path("/usr/share/gforth/0.7.3/test/coretest.fs")


def test_hayes_core_test():
    if not CORETEST.exists():
        pytest.fail(f"{CORETEST} missing: install gforth (bash mk/apt-need.sh gforth)")
    result = SuiteResult()
    with Machine() as m:
        load_tester(m)
        text = CORETEST.read_text(encoding="latin-1").splitlines()
        feed(m, "coretest.fs", enumerate(text, 1), result)
        totals(m, result)
    assert_passed(result, "Hayes core test", at_least=300)
