"""Paths, the build check, the fsync fault injector and ending pty children, shared
by the console, run and disk tests."""
import atexit
import functools
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pexpect
import pytest

from harness.machine import pty_child
from harness.machine.build import KERNEL, PDP11 as SIMULATOR, PRISTINE_DISK as PRISTINE, ROOT  # noqa: F401 (shared)
from harness.machine.pty_spawn import Spawn

needs_build = pytest.mark.skipif(
    not all(p.is_file() for p in (PRISTINE, SIMULATOR, KERNEL)),
    reason="build/pdp11, build/kernel.lda and build/robot.dsk are built by make")

# The console's waits (KEY at the prompt, a move's polling) at 100 times the 11/23's
# pace, as the pty Machine's (harness/machine/machine.py), where a test is not about it
IDLE_SPEED = ("--idle-speed", "100")

FAILING_FSYNC = "#include <errno.h>\nint fsync (int fd) { errno = EIO; return -1; }\n"


@functools.cache
def failing_fsync_library():
    """A shared library that makes every fsync fail with EIO, for LD_PRELOAD: the
    host refusing to make a write durable (pdp11-devices/simh/rl_durable.c's error
    path). Built once per test process."""
    if shutil.which("gcc") is None:
        pytest.skip("gcc is needed to build the fsync fault injector")
    directory = Path(tempfile.mkdtemp(prefix="fsync-eio-"))
    atexit.register(shutil.rmtree, directory, True)
    source, library = directory / "fsync_eio.c", directory / "fsync_eio.so"
    source.write_text(FAILING_FSYNC)
    subprocess.run(["gcc", "-shared", "-fPIC", "-o", str(library), str(source)], check=True)
    return library


def spawn(program, *args, **options):
    """pexpect.spawn in the repository, without pexpect's fixed pauses (50 ms before
    each send, 0.1 ms after each read; the one at the close: ended())."""
    child = Spawn(str(program), [str(a) for a in args], cwd=str(ROOT),
                  **{"timeout": 30, **options})
    child.delaybeforesend = child.delayafterread = None
    return child


def harness_console(*args, **options):
    """`python -m harness console ARGS` in a pty (spawn)."""
    return spawn(sys.executable, "-m", "harness", "console", *args, **options)


def ended(child, timeout=-1):
    """The exit status of a pexpect child at its end (EOF, within `timeout` s: -1 the
    child's own), closed without pexpect's fixed pause."""
    child.expect(pexpect.EOF, timeout=timeout)
    pty_child.close(child)
    return child.exitstatus


def outlived(child, seconds=30):
    """Wait for a pexpect child whose terminal was closed to exit; True if it
    is still running after `seconds` (it outlived its terminal)."""
    return not pty_child.exited(child, seconds)


def simh_command(child, command):
    """^E, one SIMH command, CONT (and the machine running again); what it printed."""
    from harness.machine.pty_child import probe_prompt
    child.send("\x05")
    child.expect("sim> ")
    child.send(command + "\r")
    child.expect("sim> ")
    printed = child.before
    child.send("cont\r")
    assert probe_prompt(child) == 0               # running again (CONT's TCSAFLUSH)
    return printed
