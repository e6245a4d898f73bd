"""The lock-step's pure logic alone: build/lockstep_test (tests/controllers/lockstep_test.c)."""
import subprocess
from pathlib import Path

LOCKSTEP_TEST = Path(__file__).resolve().parents[2] / "build" / "lockstep_test"


def test_link_and_boundary_unit_tests():
    proc = subprocess.run([str(LOCKSTEP_TEST)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.rstrip().endswith("checks, 0 failed")
    assert int(proc.stdout.split("\n")[-2].split()[0]) >= 20
