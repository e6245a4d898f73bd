"""Where things are: the repository, the build's products, the disks, and the
machine's rate. The one home for these facts; everything else imports them.

    from harness.machine import build
    build.ROOT, build.PDP11, build.KERNEL, build.KERNEL_MAP, build.PRISTINE_DISK
    disk = build.fresh_disk(tmp)          # tmp/robot.dsk, a copy of the pristine disk

The simulator is build/pdp11 unless the environment variable PDP11_SIM names
another (make exports its PDP11_SIM variable, mk/forth.mk), for every module.
"""
import os
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BUILD = ROOT / "build"
PDP11 = ROOT / os.environ.get("PDP11_SIM", "build/pdp11")  # the robot's simulator
PDP11_STOCK = BUILD / "pdp11-stock"                       # SIMH's own, for reference
PDP11_TIMED = BUILD / "pdp11-timed"        # with the CPU patch: SET CLK TIMED (11/23 time)
MACHINE_INI = ROOT / "pdp11-devices" / "machine.ini"      # the machine's configuration
KERNEL = BUILD / "kernel.lda"                             # the FORTH kernel
KERNEL_MAP = BUILD / "kernel.map"                         # its symbols (kernel_layout)
# The per-axis LSI-11/03s (issue 21, docs/controllers.md): the same kernel without
# the MMU setup (same layout: KERNEL_MAP serves both), and the SIMH commands that
# turn machine.ini's 11/23 into an 11/03 with the KEV11-A's EIS (the kernel's
# MUL and DIV); SIMH's 11/03 has 64 KB, no MMU, EIS and FIS off by default.
KERNEL_1103 = BUILD / "kernel-1103.lda"
CPU_1103 = ("set cpu 11/03", "set cpu eis")
DISK_NAME = "robot.dsk"
PRISTINE_DISK = BUILD / DISK_NAME        # as make built it: only ever copied
WORKING_DISK = ROOT / "local" / DISK_NAME  # the console's and the lab's, kept between runs
# Instructions per simulated second at power-up: the KW11-L's CLK RATE default
# (pdp11-devices/bus/kw11l.c), which SHOW CLK reports.
RATE = 300_000
# The lock-step coordinator of the five machines (issue 21, pdp11-devices/lockstep/coordinator.c)
COORDINATOR = BUILD / "lockstep-coordinator"
CONTROLLERS_DIR = ROOT / "local" / "controllers"   # make run CONTROLLERS=4's session (0700)


def fresh_disk(directory, name=DISK_NAME, source=PRISTINE_DISK):
    """A copy of `source` (the pristine disk) as directory/name; its path."""
    disk = Path(directory) / name
    shutil.copyfile(source, disk)
    return disk
