"""`make bench-harness`: how fast scripted runs and the test suite are on this host.

Prints the wall time of one scenario including the boot, in process and from
the command line (`python -m harness regress boot`, goal <= 0.25 s; best of
five), of a one-line script (`python -m harness run`, goal <= 0.15 s), of the whole regression suite (goal <= 60 s), the real-time factor
(simulated seconds per wall second for a run that is mostly #wait), the share
of a core the console's simulator takes idle at the prompt with --fast, and
the wall time of the whole pytest suite as make test runs it (issue 19's goal <= 25 s).
"""
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from harness.analysis import regression
from harness.controllers.scripted import run_five_file
from harness.machine.build import PDP11, ROOT, fresh_disk
from harness.machine.pty_spawn import Spawn
from harness.machine.script import parse
from harness.machine.script_run import run_steps
from harness.machine.scripted_machine import ScriptedMachine

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
        wall, _ = timed(lambda: [regression.run(s, tmp, five_runner=run_five_file)
                                 for s in regression.scenarios()
                                 if not regression.skip_reason(s)])
    ran = sum(1 for s in regression.scenarios() if not regression.skip_reason(s))
    return wall, ran, len(regression.scenarios())


def real_time_factor():
    with tempfile.TemporaryDirectory() as tmp:
        with ScriptedMachine(fresh_disk(tmp).name, cwd=tmp) as m:
            wall, _ = timed(lambda: run_steps(m, parse(f"#wait {IDLE_SECONDS}")))
    return IDLE_SECONDS / wall


def command_line_one_line(tries=5):
    """`python -m harness run` of a one-line script: Python's start, the imports,
    the boot and one line (issue 19: 0.075 s of CPU before, 0.067 after)."""
    with tempfile.TemporaryDirectory() as tmp:
        script = Path(tmp) / "one.script"
        script.write_text("1 2 + .\n")
        command = [sys.executable, "-m", "harness", "run", str(script)]
        return min(timed(lambda: subprocess.run(command, cwd=regression.ROOT, check=True,
                                                capture_output=True))[0] for _ in range(tries))


def command_line_scenario(tries=5):
    command = [sys.executable, "-m", "harness", "regress", "boot"]
    return min(timed(lambda: subprocess.run(command, cwd=ROOT, check=True,
                                            capture_output=True))[0] for _ in range(tries))


def cpu_seconds(pid):
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def idle_console_share(seconds=3.0, line=None):
    """Share of a core build/pdp11 uses at the FORTH prompt, as `console --fast` runs
    it, after `line` (e.g. the blocks loaded and the servo running) if given."""
    from harness.machine.console_session import boot_script
    with tempfile.TemporaryDirectory() as tmp:
        disk = fresh_disk(tmp)
        ini = Path(tmp) / "console.ini"
        ini.write_text(boot_script(disk, fast=True))
        child = Spawn(str(PDP11), [str(ini)],
                      timeout=30)
        try:
            child.expect(b" ok\r\n")
            if line:
                child.send(line.encode() + b"\r")
                child.expect(b" ok\r\n")
            time.sleep(0.5)
            before, start = cpu_seconds(child.pid), time.perf_counter()
            time.sleep(seconds)
            return (cpu_seconds(child.pid) - before) / (time.perf_counter() - start)
        finally:
            child.close(force=True)


def test_suite():
    command = ["make", "--no-print-directory", "test"]
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS")}
    return timed(lambda: subprocess.run(command, cwd=ROOT, env=env,
                                        capture_output=True))


def main():
    print("harness scripted runs (wall clock on this host):")
    print(f"  one scenario with boot (boot.script):  {one_scenario():6.3f} s   (goal <= 1 s)")
    print(f"  the same from the command line (regress boot, best of 5): "
          f"{command_line_scenario():6.3f} s   (goal <= 0.25 s)")
    print(f"  a one-line script from the command line (run, best of 5): "
          f"{command_line_one_line():6.3f} s   (goal <= 0.15 s)")
    wall, ran, total = whole_suite()
    print(f"  regression suite, {ran} of {total} scenarios runnable: {wall:6.3f} s   "
          "(goal <= 60 s)")
    print(f"  real-time factor (the FORTH idle at its prompt for {IDLE_SECONDS:g} "
          f"simulated s, no trace): {real_time_factor():6.1f} x")
    print(f"  console --fast idle at the prompt: {100 * idle_console_share():5.1f} % of a core; "
          f"with the servo running: "
          f"{100 * idle_console_share(line='1000 LOAD Set.Up.Robot'):5.1f} %")
    wall, done = test_suite()
    print(f"  make test (the whole suite, as a user runs it): {wall:6.1f} s, "
          f"exit status {done.returncode}   (goal <= 25 s; it follows the host's speed, "
          "which bench-devices' stock figure shows: 884 tests 40.8 s on a host at "
          "127 M/s; 879 tests 38.5 s at 124 M/s, 49-54 s at 76 M/s; 32 s for 579 "
          "when the goal was set)")


if __name__ == "__main__":
    main()
