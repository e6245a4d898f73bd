"""Fixtures for the ASN tests (blocks 1070-1078): the robot on a fresh copy
of build/robot.dsk, driven in lock-step (harness/machine/robot.py).

`learned` is one run for both ASN modules (session-scoped; tests/schedule.py's
SHARED_START puts the two on one worker): its first part is the scripted run
test_asn_script.py compares with `python -m harness run`'s, its trials go on
until the model's test has its steps."""
from dataclasses import dataclass
from pathlib import Path

import pytest

from harness.analysis import asn_log
from harness.figures.asn_runs import LINE_LIMIT, script_text
from harness.machine import script
from harness.machine.build import KERNEL, KERNEL_MAP, PDP11, PRISTINE_DISK, fresh_disk
from harness.machine.robot import Robot
from harness.machine.script_run import run_steps

MODEL_STEPS = 200       # the steps the model must choose as the FORTH did
SCRIPT_TRIALS = 2       # the Trial lines of the script both modules run


def asn_disk(directory):
    """A fresh copy of the pristine disk in `directory` (the build checked first)."""
    for need in (KERNEL, PDP11, PRISTINE_DISK, KERNEL_MAP):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    return fresh_disk(directory, "rl0.dsk")


@pytest.fixture
def disk(tmp_path):
    return asn_disk(tmp_path)


def n_steps(text):
    return sum(t.n_steps for t in asn_log.parse(text))


@dataclass
class Learned:
    transcript: str     # the script's (script_text(SCRIPT_TRIALS)), as `run` writes it
    trials: str         # what the Trial lines printed, one after another
    net: str            # what .Net printed after them
    disk: Path          # the disk the FORTH left (BYE's FLUSH), the net in block 1079


@pytest.fixture(scope="session")
def learned(tmp_path_factory):
    """make asn-runs' script with SCRIPT_TRIALS trials (1000 LOAD 1070 LOAD
    Set.Up.Robot, Trial lines, .Net), run by `python -m harness run`'s runner
    (script_run.run_steps) but on a disk kept after it; then on the same
    machine Trial until at least MODEL_STEPS steps (three trials, some 330
    simulated seconds in all), .Net, and leave the FORTH. The model's test
    reads what it printed, the weights' test boots its disk again."""
    directory = tmp_path_factory.mktemp("asn")
    disk = asn_disk(directory)
    path = directory / "asn.script"
    path.write_text(script_text(SCRIPT_TRIALS))
    with Robot(disk=disk, timeout=LINE_LIMIT) as r:
        result = run_steps(r, script.read(path))
        assert not result.failures, result.failures
        trials = result.transcript
        while n_steps(trials) < MODEL_STEPS:
            trials += r.send("Trial") + "\n"
        net = r.send(".Net")
    return Learned(result.transcript, trials, net, disk)
