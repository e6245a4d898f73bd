"""gforth's packaged tests of the other word sets (CORE EXT, DOUBLE, SEARCH,
STRING, DEFER), fed through the console on one boot.

The files are read from the installed gforth package at test time (never
copied here). Lines that use gforth's own words (D<> D> D>= D<= STR= ROOT,
floating point) or `require` other files are skipped and counted; STR= gets a
stand-in defined with COMPARE, MAX-UINT and MIN-INT come from coretest."""
from pathlib import Path

import pytest

from harness.machine import Machine

SUITES = Path("/usr/share/gforth/0.7.3/test")
FILES = ("coreext.fs", "dbltest.fs", "search.fs", "string.fs", "deferred.fs")
TESTER = Path(__file__).with_name("tester.fs")
GFORTH_ONLY = ("d<>", "d>", "d>=", "d<=", "root", "5e", "require")
PRELUDE = ("DECIMAL",
           ": STR=  ( a1 u1 a2 u2 -- f )  COMPARE 0= ;",
           "0 INVERT CONSTANT MAX-UINT",
           "0 INVERT 1 RSHIFT INVERT CONSTANT MIN-INT")


def gforth_only(line):
    words = line.lower().split()
    return any(w in GFORTH_ONLY for w in words)


def test_gforth_word_set_tests():
    missing = [f for f in FILES if not (SUITES / f).exists()]
    if missing:
        pytest.fail(f"{SUITES}/{missing[0]} missing: install gforth (bash mk/apt-need.sh gforth)")
    skipped, errors, failed_lines = 0, [], []
    with Machine() as m:
        for line in TESTER.read_text().splitlines() + list(PRELUDE):
            m.send(line)
        for name in FILES:
            for n, line in enumerate((SUITES / name).read_text(encoding="latin-1").splitlines(), 1):
                if gforth_only(line):
                    skipped += 1
                    continue
                r = m.reply(line)
                if not r.ok:
                    errors.append(f"{name}:{n}: {line.strip()} -> {r.error}")
                if "TEST FAILED" in r.output:
                    failed_lines.append(f"{name}:{n}: {r.output.strip()}")
        m.send("DECIMAL")
        tests = int(m.send("#TESTS @ .").split()[0])
        failed = int(m.send("#FAILED @ .").split()[0])
    print(f"\ngforth word-set tests: {tests} tests, {failed} failed, "
          f"{len(errors)} lines with errors, {skipped} gforth-only lines skipped")
    assert not errors, "\n".join(errors[:20])
    assert failed == 0 and not failed_lines, "\n".join(failed_lines[:20])
    assert tests > 80
