"""Fixtures for the FORTH tests: a booted machine per module (fresh disk)."""
import pytest

from harness.machine.machine import KERNEL, SIMULATOR, Machine


@pytest.fixture(scope="module")
def forth():
    if not KERNEL.exists() or not SIMULATOR.exists():
        pytest.fail(f"build first: {KERNEL} and {SIMULATOR} (make kernel build/pdp11)")
    with Machine() as m:
        yield m
