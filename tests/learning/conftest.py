"""Fixtures for the ASN tests (blocks 1070-1078): the robot on a fresh copy
of build/robot.dsk, driven in lock-step (harness/machine/robot.py)."""
from dataclasses import dataclass
from pathlib import Path

import pytest

from harness.analysis import asn_log
from harness.machine.build import KERNEL, KERNEL_MAP, PDP11, PRISTINE_DISK, fresh_disk
from harness.machine.robot import Robot

MODEL_STEPS = 200       # the steps the model must choose as the FORTH did


def asn_disk(directory):
    """A fresh copy of the pristine disk in `directory` (the build checked first)."""
    for need in (KERNEL, PDP11, PRISTINE_DISK, KERNEL_MAP):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    return fresh_disk(directory, "rl0.dsk")


@pytest.fixture
def disk(tmp_path):
    return asn_disk(tmp_path)


@dataclass
class Learned:
    trials: str         # what the Trial lines printed, one after another
    net: str            # what .Net printed after them
    disk: Path          # the disk the FORTH left (BYE's FLUSH), the net in block 1079


@pytest.fixture(scope="module")
def learned(tmp_path_factory):
    """1000 LOAD 1070 LOAD Set.Up.Robot, Trial until at least MODEL_STEPS steps
    (three trials, some 330 simulated seconds), .Net, then leave the FORTH.
    One run for the module: the model's test reads what it printed, the
    weights' test boots its disk again."""
    disk = asn_disk(tmp_path_factory.mktemp("asn"))
    with Robot(disk=disk, timeout=600) as r:
        assert r.send("1000 LOAD 1070 LOAD") == ""
        assert r.send("Set.Up.Robot") == ""
        out = ""
        while sum(t.n_steps for t in asn_log.parse(out)) < MODEL_STEPS:
            out += r.send("Trial") + "\n"
        net = r.send(".Net")
    return Learned(out, net, disk)
