"""Harness tests: their helper modules (servo_program) live here; one real
trace from build/pdp11, made once per session, serves the trace, moves and plot
tests; `cli` runs the command line in the test's own process."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from harness.cli import main  # noqa: E402
from harness.machine import simh  # noqa: E402
from servo_program import servo_program, trace_script  # noqa: E402


@pytest.fixture(scope="session")
def servo_trace(tmp_path_factory):
    """Path of the trace of the hand servo's run: idle, long move, short move,
    held code raised three times (tests/harness/servo_program.py)."""
    path = tmp_path_factory.mktemp("trace") / "servo.csv"
    simh.run(trace_script(servo_program(), path))
    return path


@pytest.fixture
def cli(capsys):
    """cli(*argv) -> (exit status, stdout, stderr) of `python -m harness ARGV`, run
    in this process (harness.cli.main, what __main__ calls; a usage error's exit
    as its status). Each command-line module keeps one real `python -m harness`
    subprocess for the start itself; the rest need not pay a Python's start each."""
    def run(*argv):
        try:
            status = main([str(a) for a in argv])
        except SystemExit as exit_:
            status = exit_.code
        out, err = capsys.readouterr()
        return status, out, err
    return run
