"""gforth's packaged tests of the other word sets (CORE EXT, DOUBLE, SEARCH,
STRING, DEFER), fed through the console on one boot.

The files are read from the installed gforth package at test time (never
copied here). Lines that use gforth's own words (D<> D> D>= D<= STR= ROOT,
floating point) or `require` other files are skipped and counted; STR= gets a
stand-in defined with COMPARE, MAX-UINT and MIN-INT come from coretest."""
from pathlib import Path

import pytest

from harness.machine.machine import Machine
from tests.forth.suite import SuiteResult, assert_passed, feed, load_tester, totals

SUITES = Path("/usr/share/gforth/0.7.3/test")
FILES = ("coreext.fs", "dbltest.fs", "search.fs", "string.fs", "deferred.fs")
GFORTH_ONLY = ("d<>", "d>", "d>=", "d<=", "root", "5e", "require")
PRELUDE = ("DECIMAL",
           ": STR=  ( a1 u1 a2 u2 -- f )  COMPARE 0= ;",
           "0 INVERT CONSTANT MAX-UINT",
           "0 INVERT 1 RSHIFT INVERT CONSTANT MIN-INT")


def gforth_only(line):
    return any(w in GFORTH_ONLY for w in line.lower().split())


def test_gforth_word_set_tests():
    missing = [f for f in FILES if not (SUITES / f).exists()]
    if missing:
        pytest.fail(f"{SUITES}/{missing[0]} missing: install gforth (bash mk/apt-need.sh gforth)")
    result, skipped = SuiteResult(), 0
    with Machine() as m:
        load_tester(m, *PRELUDE)
        for name in FILES:
            text = (SUITES / name).read_text(encoding="latin-1").splitlines()
            kept = [(n, line) for n, line in enumerate(text, 1) if not gforth_only(line)]
            skipped += len(text) - len(kept)
            feed(m, name, kept, result)
        totals(m, result)
    assert_passed(result, "gforth word-set tests", f", {skipped} gforth-only lines skipped",
                  at_least=80)
