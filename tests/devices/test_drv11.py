"""DRV11 (counter multiplexer): register bits, byte writes, INIT, interrupts."""
import pytest

from programs import examine_results, results
from harness.machine import simh
import programs


def test_drv11_register_bits_bytes_and_init():
    out = simh.run(programs.drv_bits().script() + examine_results(10))
    assert "HALT instruction" in out
    assert results(out, 10) == [
        0o143,      # CSR: select 3, INT ENB A and B; REQ bits and the rest read 0
        0o143,      # a write to the high byte changes nothing (REQ B is read-only)
        0o002,      # low-byte write: select 2, INT ENBs cleared
        0,
        0o123456,   # OUTBUF latches all 16 bits
        0o177456,   # high byte only
        0o177400,   # low byte only
        0,          # INBUF ignores writes; x's counter is held at 0
        0, 0,       # bus INIT clears CSR and OUTBUF
    ]


def run_requests(csr, sets, psw=0):
    prog = programs.drv_interrupts(csr)
    out = simh.run(prog.script(psw=psw, start=False) + "step 100\n" + sets +
                   "step 1000\n" + examine_results(2) + "examine drv11 csr\n")
    assert out.count("Step expired") == 2 + sets.count("step"), out
    return results(out, 2)


@pytest.mark.parametrize("csr,sets,expected", [
    (0o100, "set drv11 reqa=1\n", [1, 0]),                 # A: vector 300, once per rising REQ
    (0o040, "set drv11 reqb=1\n", [0, 1]),                 # B: vector 304
    (0o140, "set drv11 reqa=1\nset drv11 reqb=1\n", [1, 1]),
    (0o000, "set drv11 reqa=1\nset drv11 reqb=1\n", [0, 0]),   # no INT ENB: none
    (0o040, "set drv11 reqa=1\n", [0, 0]),                 # REQ A without INT ENB A
    (0o100, "set drv11 reqa=1\nstep 100\nset drv11 reqa=0\nset drv11 reqa=1\n", [2, 0]),
])
def test_drv11_interrupts(csr, sets, expected):
    assert run_requests(csr, sets) == expected


def test_drv11_interrupts_wait_for_priority_below_4():
    assert run_requests(0o100, "set drv11 reqa=1\n", psw=0o200) == [0, 0]


def test_req_bits_read_back_in_csr():
    out = simh.run("set drv11 reqa=1\nset drv11 reqb=1\nexamine drv11 csr\nshow drv11\n"
                   "set drv11 reqa=2\nset drv11 reqb\n")
    assert "REQA=1 REQB=1" in out
    assert out.count("REQA and REQB take 0 or 1") == 2
