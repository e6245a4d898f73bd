"""SET CLK TIMED (pdp11-devices/simh/kdf11_time.c and the one-line CPU patch): each
instruction advances simulated time by its KDF11-A time from the table that
harness/analysis/kdf11.py prices by; with the mode off the patched CPU (build/pdp11-timed) counts as SIMH's stock one
does."""
import re

from harness.analysis import kdf11_table
from harness.analysis.pdp11prog import Program, check_listing
from harness.machine import simh
from harness.machine.build import PDP11_STOCK, PDP11_TIMED

LOOPS = 64


def mixed_loop():
    """R1 counts down from LOOPS; ADD, MOV, MUL, DEC, BNE each pass; then HALT.
    The words executed, in order, for pricing."""
    p = Program()
    p.op("MOV #100,R1", 0o012701, LOOPS)
    top = p.here
    body = [("ADD R1,R2", 0o060102), ("MOV R2,R3", 0o010203), ("MUL R1,R3", 0o070301),
            ("DEC R1", 0o005301)]
    for text, word in body:
        p.op(text, word)
    bne = 0o001000 | ((top - p.here - 2) // 2 & 0o377)
    p.op(f"BNE {top:o}", bne)
    p.op("HALT", 0o000000)
    return p, [0o012701] + ([w for _, w in body] + [bne]) * LOOPS + [0o000000]


def run(prog, simulator, extra=""):
    out = simh.run(extra + prog.script() + "show time\nexamine r0:r5\nexamine psw\n",
                   simulator=simulator)
    assert "HALT instruction" in out, out
    return out


def time_of(out):
    return int(re.search(r"Time:\s*(\d+)", out).group(1))


def registers(out):
    return {k: v for k, v in simh.examined(out).items() if k[0] in "RP"}


def test_the_program_is_what_simh_disassembles():
    prog, _ = mixed_loop()
    assert check_listing(prog) == []


def test_mode_off_counts_as_stock_simh_does():
    prog, executed = mixed_loop()
    stock, ours = run(prog, PDP11_STOCK), run(prog, PDP11_TIMED)
    assert time_of(stock) == time_of(ours) == len(executed)
    assert registers(stock) == registers(ours) and registers(ours)


def test_timed_each_instruction_takes_its_kdf11_time():
    prog, executed = mixed_loop()
    out = run(prog, PDP11_TIMED, extra="set clk timed\n")
    assert time_of(out) == sum(kdf11_table.units(w) for w in executed)   # 75 ns units
    assert "rate=13333333 units" in simh.run("set clk timed\nshow clk rate\n",
                                             simulator=PDP11_TIMED)
    # MUL (33.075 us + register source 1.275) dominates: far from one count each
    assert time_of(out) > 10 * len(executed)


def test_notimed_returns_to_the_rate_before():
    out = simh.run("set clk rate=150000\nset clk timed\nset clk notimed\nshow clk rate\n",
                   simulator=PDP11_TIMED)
    assert "rate=150000 instructions/s" in out


def test_build_pdp11_keeps_simhs_cpu_and_refuses_timed():
    out = simh.run("set clk timed\nshow clk rate\n")
    assert "TIMED needs the CPU that prices instructions: build/pdp11-timed" in out
    assert "rate=300000 instructions/s" in out
