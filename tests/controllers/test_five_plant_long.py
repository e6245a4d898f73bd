"""The rack switched off and on at the 11/23's sim> during a move of the five
machines (make test-controllers-long; make test has the short version,
test_five_plant.py): the FORTH of blocks 1080-1089 on the four 11/03s and
1200-1206 on the 11/23, scripted (`#simh` lines are typed at the 11/23's sim>
between its FORTH lines). While the rack is off the 11/03s' servos write their
move's velocity to the D/As and no drive reaches an axis (the trace's vcmd is 0
on every row); switched on, the move resumes and Move.Complete? returns. Two
runs give the same bytes on all five consoles and in the trace. The same at
`make run CONTROLLERS=4`, typed at the 11/23's console as a teacher would."""
import csv
import io
import json
import os
import re

import pytest

from harness.controllers.scripted import run_five
from harness.machine import script

pytestmark = pytest.mark.skipif(not os.environ.get("CONTROLLERS_LONG"),
                                reason="the long five-machine runs run with make test-controllers-long")
SCRIPT = """1200 LOAD
Set.Up.Robot
#simh set plant power=off
#simh show plant
2000 1000 800 0 Abs.Move
#wait 1
#simh set plant power=on
#simh show plant
Move.Complete?
.Axes
"""
HOLD = 50                # counts: the printed servo's hunting (docs/controllers.md)
TARGETS = {"X": 2000, "Y": 1000, "Z": 800}


def switched_at(show):
    """A SET typed at sim> takes effect at the boundary after the last one SHOW names."""
    return round(float(re.search(r"time=([\d.]+)s", show).group(1)) + 0.001, 6)


def test_the_rack_off_at_sim_stops_the_drive_and_on_again_the_move_completes(tmp_path):
    steps = script.parse(SCRIPT, "five-plant")
    runs = []
    for name in ("first", "second"):
        (tmp_path / name).mkdir()
        runs.append(run_five(steps, tmp_path / name))
    first, second = runs
    assert not first.failures, first.failures
    assert first.transcripts == second.transcripts
    assert first.trace == second.trace
    main = first.transcripts["main"]
    shows = main.split("PLANT, ")[1:]
    assert "power=off" in shows[0] and "power=on" in shows[1]
    t_off, t_on = switched_at(shows[0]), switched_at(shows[1])
    assert t_on - t_off > 1.0                          # the #wait 1 and the Abs.Move line
    rows = list(csv.DictReader(io.StringIO(first.trace.decode())))
    off = [r for r in rows if t_off < float(r["time_s"]) < t_on]
    # the rack off: the 11/03s command the move (their D/A codes far from 2048) ...
    assert {r["axis"] for r in off if abs(int(r["dac"]) - 2048) > 250} >= set(TARGETS)
    # ... and no drive reaches any axis: every row's vcmd is 0, the axes come to rest
    assert off and all(float(r["vcmd"]) == 0 for r in off)
    last = {r["axis"]: r for r in off}
    assert all(abs(float(last[a]["vel"])) < 1 for a in TARGETS)
    assert all(abs(int(last[a]["counter"])) < HOLD for a in TARGETS)    # the move not begun
    # switched on again: driven at once, and the move completes (.Axes)
    after = [r for r in rows if t_on < float(r["time_s"]) < t_on + 0.02]
    assert any(float(r["vcmd"]) != 0 for r in after if r["axis"] in TARGETS)
    counters = dict(re.findall(r"^([xyz]) +-?\d+ +(-?\d+) ", main, re.M))
    for a, target in TARGETS.items():
        assert abs(int(counters[a.lower()]) - target) <= HOLD, (a, counters)


def test_a_teacher_switches_the_rack_at_make_run_controllers(tmp_path):
    """^E, SET PLANT POWER=OFF, CONT at `make run CONTROLLERS=4`: the coordinator's
    rack goes off (its status, the lab page's source; SHOW PLANT at the 11/23), a move
    waits; ^E, SET PLANT POWER=ON, CONT: it completes."""
    from tests.controllers.test_lockstep_launch import launch_booted, leave
    from tests.run.common import simh_command
    child, _, session = launch_booted(tmp_path)

    def at_sim(command):
        return simh_command(child, command)

    for line in ("1200 LOAD", "Set.Up.Robot"):
        child.send(line + "\r")
        child.expect(" ok")
    at_sim("set plant power=off")
    child.send("2000 1000 800 0 Abs.Move\r")
    child.expect(" ok")
    assert "power=off" in at_sim("show plant")
    assert json.loads((session / "status.json").read_text())["power"] == 0
    child.send(".Axes\r")                              # nothing moved
    child.expect(r"x +2000 +(-?\d+) ")
    assert abs(int(child.match.group(1))) < HOLD
    at_sim("set plant power=on")
    child.send("Move.Complete? .Axes\r")
    child.expect(r"x +2000 +(-?\d+) ")
    assert abs(int(child.match.group(1)) - 2000) <= HOLD
    child.expect(" ok")
    assert leave(child) == 0
