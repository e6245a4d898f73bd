"""SIMH's EXAMINE and DEPOSIT at a project device register's I/O-page address
(160000-177777, as the CPU addresses it) show and set what the CPU sees
(pdp11-devices/simh/io_page_examine.c), before the first run as after it."""

import pytest

from harness.machine.build import fresh_disk
from harness.machine.robot import Robot, numbers
from harness.machine.simh import run

REGISTERS = {0o177546: "KW11-L LKS", 0o167770: "DRV11 CSR", 0o167772: "DRV11 OUTBUF",
             0o170440: "DAC x", 0o170442: "DAC y", 0o170444: "DAC z", 0o170446: "DAC t"}


@pytest.fixture
def forth(tmp_path):
    with Robot(disk=fresh_disk(tmp_path, "rl0.dsk")) as r:
        yield r


def examined(robot, addr):
    return int(robot.simh(f"examine {addr:o}").split(":")[1].split()[0], 8)


def test_examine_shows_what_the_cpu_reads(forth):
    forth.send("100O 177546O !  1 167770O !  5 167772O !  2100 170442O !")
    forth.idle(0.1)                                       # a tick sets LKS's monitor bit
    for addr, name in REGISTERS.items():
        cpu = numbers(forth.send(f"{addr:o}O @ U."))[0]
        assert examined(forth, addr) == cpu, name
    assert examined(forth, 0o177546) == 0o300            # IE and MON, as the CPU reads it
    assert examined(forth, 0o170442) == 2100


def test_deposit_sets_what_the_cpu_reads(forth):
    for addr, value in ((0o170444, 0o2222), (0o167772, 0o17)):
        forth.simh(f"deposit {addr:o} {value:o}")
        assert numbers(forth.send(f"{addr:o}O @ U."))[0] == value
    for ie in (0o100, 0):                   # LKS: IE as deposited (MON is set by ticks)
        forth.simh(f"deposit 177546 {ie:o}")
        assert numbers(forth.send("177546O @ U."))[0] & 0o100 == ie


def test_examine_before_the_first_run():
    out = run("deposit 170446 3000\nexamine 170446\nexamine 17777546\n")
    assert "170446:\t003000" in out and "17777546:\t000000" in out
    assert "Address space exceeded" not in out
