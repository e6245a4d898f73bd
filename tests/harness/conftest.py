"""Harness tests: their helper modules (servo_program) live here; one real
trace from build/pdp11, made once per session, serves the trace, moves and plot
tests; `cli` runs the command line in the test's own process."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from harness.machine import simh  # noqa: E402
from servo_program import servo_program, trace_script  # noqa: E402
from tests.cli_in_process import harness_here  # noqa: E402


@pytest.fixture(scope="session")
def servo_trace(tmp_path_factory):
    """Path of the trace of the hand servo's run: idle, long move, short move,
    held code raised three times (tests/harness/servo_program.py)."""
    path = tmp_path_factory.mktemp("trace") / "servo.csv"
    simh.run(trace_script(servo_program(), path))
    return path


@pytest.fixture
def cli():
    """cli(*argv) -> (exit status, stdout, stderr) of `python -m harness ARGV`, run
    in this process (tests/cli_in_process.py)."""
    def run(*argv):
        result = harness_here(*argv)
        return result.returncode, result.stdout, result.stderr
    return run
