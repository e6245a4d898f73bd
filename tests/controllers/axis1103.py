"""One LSI-11/03 with the ordinary device set (issue 21's axis controller before
the lock-step's link devices): build/kernel-1103.lda on build/pdp11 switched to
an 11/03 (harness.machine.build.CPU_1103), driven in lock-step like the 11/23's
robot tests. Without a multiplexer select the ordinary DRV11 reads x's counter
and D/A channel 0 drives x, so this 11/03 servos the plant's x axis."""
import pytest

from harness.machine.build import CPU_1103, KERNEL_1103
from tests.booted_robots import booted_robots


@pytest.fixture
def lsi11(tmp_path):
    """lsi11(trace=False) -> a Robot: the 11/03 kernel on a fresh disk."""
    yield from booted_robots(tmp_path, KERNEL_1103, settings=CPU_1103)
