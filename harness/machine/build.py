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
DISK_NAME = "robot.dsk"
PRISTINE_DISK = BUILD / DISK_NAME        # as make built it: only ever copied
WORKING_DISK = ROOT / "local" / DISK_NAME  # the console's and the lab's, kept between runs
# Instructions per simulated second at power-up: the KW11-L's CLK RATE default
# (pdp11-devices/bus/kw11l.c), which SHOW CLK reports.
RATE = 300_000


def fresh_disk(directory, name=DISK_NAME, source=PRISTINE_DISK):
    """A copy of `source` (the pristine disk) as directory/name; its path."""
    disk = Path(directory) / name
    shutil.copyfile(source, disk)
    return disk
