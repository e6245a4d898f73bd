"""`python -m harness` from a Python without the pinned packages (the system's,
outside .venv) runs itself again with .venv's Python instead of failing on an
import (issue 18)."""
import subprocess
import sys
from pathlib import Path

import pytest

from harness.machine.build import ROOT

BASE_PYTHON = Path(sys.base_prefix) / "bin" / "python3"


def test_the_system_python_runs_the_harness_through_the_venv():
    if not BASE_PYTHON.exists() or subprocess.run(
            [str(BASE_PYTHON), "-c", "import numpy"], capture_output=True).returncode == 0:
        pytest.skip(f"{BASE_PYTHON} has numpy: nothing to re-run")
    done = subprocess.run([str(BASE_PYTHON), "-m", "harness", "plot", "--help"], cwd=ROOT,
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and "usage: python -m harness plot" in done.stdout, done.stderr
