"""Fixtures for the robot tests: the appendix blocks loaded on build/pdp11,
driven in lock-step with simulated time (harness/machine/robot.py)."""
import pytest

from harness.machine.build import KERNEL
from tests.booted_robots import booted_robots

# Helpers typed at the prompt (not in the blocks): print the four counters,
# the four cells of one of the appendix's arrays, and (with the servo's clock
# interrupt off) put every DAC at its 0-Vel code so that the axes only creep.
HELPERS = (": .C ( -- ) 4 0 DO I Read.Counter . LOOP ;",
           ": A. ( array -- ) 4 0 DO DUP I 2* + @ . LOOP DROP ;",
           ": HOLD ( -- ) 4 0 DO 0-Vel I 2* + @ VelOut I 2* + ! LOOP ;")


@pytest.fixture
def boot(tmp_path):
    """boot(trace=False) -> a Robot on a fresh copy of build/robot.dsk."""
    yield from booted_robots(tmp_path, KERNEL)


@pytest.fixture
def robot(boot):
    """1000 LOAD, Set.Up.Robot and the helpers, with a plant trace."""
    r = boot(trace=True)
    assert r.send("1000 LOAD Set.Up.Robot") == ""
    for h in HELPERS:
        r.send(h)
    return r
