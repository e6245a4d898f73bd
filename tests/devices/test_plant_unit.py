"""The plant physics alone: build/plant_test (tests/devices/plant_test.c)."""
import subprocess
from pathlib import Path

PLANT_TEST = Path(__file__).resolve().parents[2] / "build" / "plant_test"


def test_plant_physics_unit_tests():
    proc = subprocess.run([str(PLANT_TEST)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.rstrip().endswith("checks, 0 failed")
    assert int(proc.stdout.split("\n")[-2].split()[0]) >= 20
