"""Robots booted on fresh copies of the pristine disk, for a fixture: the 11/23's
(tests/robot) and the 11/03's (tests/controllers) differ only in kernel and CPU."""
import pytest

from harness.machine.build import KERNEL_MAP, PDP11, PRISTINE_DISK, fresh_disk
from harness.machine.robot import Robot


def booted_robots(tmp_path, kernel, **robot_options):
    """A fixture's body (`yield from`): yields start(trace=False) -> a Robot on
    `kernel`, each on its own disk copy and trace; closes them all afterwards."""
    for need in (kernel, KERNEL_MAP, PDP11, PRISTINE_DISK):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    robots = []

    def start(trace=False):
        disk = fresh_disk(tmp_path, f"rl0-{len(robots)}.dsk")
        path = tmp_path / f"trace-{len(robots)}.csv" if trace else None
        r = Robot(disk=disk, trace=path, kernel=kernel, timeout=20,  # a hung line fails fast
                  **robot_options)
        r.trace_path = path
        robots.append(r)
        return r

    yield start
    for r in robots:
        r.close()
