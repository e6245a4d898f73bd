"""Paths, the build check and the fsync fault injector shared by the console, run
and disk tests."""
import shutil
import subprocess
from pathlib import Path

import pytest

from harness.machine.build import KERNEL, PDP11 as SIMULATOR, PRISTINE_DISK as PRISTINE, ROOT  # noqa: F401 (shared)

needs_build = pytest.mark.skipif(
    not all(p.is_file() for p in (PRISTINE, SIMULATOR, KERNEL)),
    reason="build/pdp11, build/kernel.lda and build/robot.dsk are built by make")


FAILING_FSYNC = "#include <errno.h>\nint fsync (int fd) { errno = EIO; return -1; }\n"


def failing_fsync_library(directory):
    """A shared library that makes every fsync fail with EIO, for LD_PRELOAD: the
    host refusing to make a write durable (pdp11-devices/simh/rl_durable.c's error path)."""
    if shutil.which("gcc") is None:
        pytest.skip("gcc is needed to build the fsync fault injector")
    source, library = Path(directory) / "fsync_eio.c", Path(directory) / "fsync_eio.so"
    source.write_text(FAILING_FSYNC)
    subprocess.run(["gcc", "-shared", "-fPIC", "-o", str(library), str(source)], check=True)
    return library


def outlived(child, seconds=30):
    """Wait for a pexpect child whose terminal was closed to exit; True if it
    is still running after `seconds` (it outlived its terminal)."""
    import time
    deadline = time.monotonic() + seconds
    while child.ptyproc.isalive() and time.monotonic() < deadline:
        time.sleep(0.05)
    return child.ptyproc.isalive()
