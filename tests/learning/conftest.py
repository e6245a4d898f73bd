"""Fixtures for the ASN tests (blocks 1070-1078): the robot on a fresh copy
of build/robot.dsk, driven in lock-step (harness/machine/robot.py)."""
import shutil

import pytest

from harness.machine.machine import KERNEL, SIMULATOR
from harness.machine.robot import MAP, Robot

DISK = KERNEL.parent / "robot.dsk"


@pytest.fixture
def disk(tmp_path):
    for need in (KERNEL, SIMULATOR, DISK, MAP):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    path = tmp_path / "rl0.dsk"
    shutil.copy(DISK, path)
    return path


@pytest.fixture
def asn(disk):
    """1000 LOAD 1070 LOAD Set.Up.Robot: the ASN ready for Trial."""
    with Robot(disk=disk, timeout=600) as r:
        assert r.send("1000 LOAD 1070 LOAD") == ""
        assert r.send("Set.Up.Robot") == ""
        yield r
