"""Fixtures for the ASN tests (blocks 1070-1078): the robot on a fresh copy
of build/robot.dsk, driven in lock-step (harness/machine/robot.py)."""
import pytest

from harness.machine.build import KERNEL, KERNEL_MAP, PDP11, PRISTINE_DISK, fresh_disk
from harness.machine.robot import Robot


@pytest.fixture
def disk(tmp_path):
    for need in (KERNEL, PDP11, PRISTINE_DISK, KERNEL_MAP):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    return fresh_disk(tmp_path, "rl0.dsk")


@pytest.fixture
def asn(disk):
    """1000 LOAD 1070 LOAD Set.Up.Robot: the ASN ready for Trial."""
    with Robot(disk=disk, timeout=600) as r:
        assert r.send("1000 LOAD 1070 LOAD") == ""
        assert r.send("Set.Up.Robot") == ""
        yield r
