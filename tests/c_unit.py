"""The pure C parts' own test programs (build/plant_test, gripper_test,
lockstep_test): each prints "N checks, F failed" last and exits non-zero on a
failure."""
import subprocess
from pathlib import Path

BUILD = Path(__file__).resolve().parents[1] / "build"


def passes(program, at_least=1):
    """Run build/`program`: every check passed, and there were at least `at_least`."""
    proc = subprocess.run([str(BUILD / program)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    last = proc.stdout.rstrip().split("\n")[-1]
    assert last.endswith("checks, 0 failed"), proc.stdout
    assert int(last.split()[0]) >= at_least, last
    return True
