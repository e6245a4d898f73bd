"""`make bench-harness`: how fast scripted runs are on this host (wall clock).

Prints the wall time of one scenario including the boot (goal <= 1 s), of the
whole regression suite (goal <= 60 s), and the real-time factor: simulated
seconds per wall second for a run that is mostly simulated time (#wait).
"""
import tempfile
import time
from pathlib import Path

from harness import regression
from harness.script import parse
from harness.script_run import run_steps
from harness.scripted_machine import ScriptedMachine

IDLE_SECONDS = 20.0


def timed(function):
    start = time.perf_counter()
    result = function()
    return time.perf_counter() - start, result


def one_scenario(name="boot"):
    scenario = regression.Scenario(regression.SCENARIOS / f"{name}.script")
    with tempfile.TemporaryDirectory() as tmp:
        return timed(lambda: regression.run(scenario, tmp))[0]


def whole_suite():
    with tempfile.TemporaryDirectory() as tmp:
        wall, _ = timed(lambda: [regression.run(s, tmp) for s in regression.scenarios()
                                 if not regression.skip_reason(s)])
    ran = sum(1 for s in regression.scenarios() if not regression.skip_reason(s))
    return wall, ran, len(regression.scenarios())


def real_time_factor():
    with tempfile.TemporaryDirectory() as tmp:
        disk = Path(tmp) / "robot.dsk"
        disk.write_bytes(regression.ROOT.joinpath("build", "robot.dsk").read_bytes())
        with ScriptedMachine("robot.dsk", cwd=tmp) as m:
            wall, _ = timed(lambda: run_steps(m, parse(f"#wait {IDLE_SECONDS}")))
    return IDLE_SECONDS / wall


def main():
    print("harness scripted runs (wall clock on this host):")
    print(f"  one scenario with boot (boot.script):  {one_scenario():6.3f} s   (goal <= 1 s)")
    wall, ran, total = whole_suite()
    print(f"  regression suite, {ran} of {total} scenarios runnable: {wall:6.3f} s   "
          "(goal <= 60 s)")
    print(f"  real-time factor (the FORTH idle at its prompt for {IDLE_SECONDS:g} "
          f"simulated s, no trace): {real_time_factor():6.1f} x")


if __name__ == "__main__":
    main()
