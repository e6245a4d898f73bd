"""Paths and the build check shared by the console and run tests."""
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PRISTINE = ROOT / "build" / "robot.dsk"
SIMULATOR = ROOT / "build" / "pdp11"
KERNEL = ROOT / "build" / "kernel.lda"

needs_build = pytest.mark.skipif(
    not all(p.is_file() for p in (PRISTINE, SIMULATOR, KERNEL)),
    reason="build/pdp11, build/kernel.lda and build/robot.dsk are built by make")
