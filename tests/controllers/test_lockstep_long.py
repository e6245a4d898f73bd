"""The long five-machine runs (make test-controllers-long; make test has one
end-to-end move, tests/controllers/test_axis_link.py and the regression scenario
controllers-move, and the kill at the launcher with the 11/03s at their prompts):
- the end-to-end move run twice: byte-identical transcripts on all five consoles
  and an identical plant trace, the move complete on x, y and z;
- a kill of one 11/03 while the five run the servos, at `make run CONTROLLERS=4`:
  reported within a second, the 11/23's next move refused naming the axis, BYE
  leaving cleanly."""
import os
import re
import signal
import time

import pexpect
import pytest

from harness.analysis import regression
from harness.controllers.scripted import run_five
from harness.machine import script
from harness.machine.build import KERNEL_1103
from tests.controllers.test_lockstep_launch import launch_booted, leave

pytestmark = pytest.mark.skipif(not os.environ.get("CONTROLLERS_LONG"),
                                reason="the long five-machine runs run with make test-controllers-long")
SCENARIO = regression.SCENARIOS / "controllers-move.script"
HOLD = 50                # counts: the printed servo's hunting (docs/controllers.md)


def test_the_move_twice_is_byte_identical_and_complete(tmp_path):
    steps = script.read(SCENARIO)
    runs = []
    for name in ("first", "second"):
        (tmp_path / name).mkdir()
        runs.append(run_five(steps, tmp_path / name, axis_kernel=KERNEL_1103))
    first, second = runs
    assert not first.failures, first.failures
    assert first.transcripts == second.transcripts
    assert first.trace == second.trace
    rows = dict((a, int(c)) for a, c in re.findall(
        r"^([xyz]) +-?\d+ +(-?\d+) ", first.transcripts["main"], re.M))
    for a, target in zip("xyz", (2000, 1000, 800)):
        assert abs(rows[a] - target) <= HOLD, (a, rows)


def test_a_kill_during_the_servos_is_reported_and_the_rest_goes_on(tmp_path):
    child, pids, session = launch_booted(tmp_path)
    for line, answer in (("1200 LOAD", " ok"), ("Set.Up.Robot", " ok"),
                         ("2000 1000 800 0 Abs.Move", " ok")):
        child.send(line + "\r")
        child.expect(answer)
    killed = time.monotonic()
    os.kill(pids["y"], signal.SIGKILL)
    child.expect("11/03 axis y stopped: its simulator is gone")
    assert time.monotonic() - killed < 1.0
    child.send("0 0 0 0 Abs.Move\r")
    child.expect("Error: 11/03 axis y stopped")
    child.send("0 Read.Counter .\r")                  # x still answers
    child.expect(r"0 Read.Counter \. (-?\d+)  ok")
    assert leave(child) == 0
