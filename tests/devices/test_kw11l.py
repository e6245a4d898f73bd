"""KW11-L line clock (CLK): register bits, INIT, exactly 60 ticks per simulated
second, interrupts at vector 100 only with IE set and priority below 6."""
import time

import pytest

from programs import examine_results, results
from harness.machine import simh
import programs

RATE = 300000


def test_lks_register_bits_bytes_and_init():
    out = simh.run(programs.lks_bits().script() + examine_results(9))
    assert "HALT instruction" in out
    assert results(out, 9) == [0o100, 0, 0, 0o100, 0, 0o200, 0o200, 0o100, 0]


def count_ticks(instructions, enable=True, psw=0, extra=""):
    prog = programs.clock_counter(enable)
    out = simh.run(extra + prog.script(psw=psw, start=False) +
                   f"step {instructions}\n" + examine_results(1) + "examine clk ticks\n")
    assert "Step expired" in out, out          # no stray trap halted it
    return results(out, 1)[0], simh.examined(out, radix=10)["TICKS"]


def test_exactly_600_ticks_in_10_simulated_seconds():
    half_tick = RATE // 120
    assert count_ticks(10 * RATE + half_tick) == (600, 600)
    assert count_ticks(10 * RATE - half_tick) == (599, 599)


def test_rate_is_settable_and_ticks_follow_it():
    assert count_ticks(5 * 150000 + 1250, extra="set clk rate=150000\n") == (300, 300)


@pytest.mark.parametrize("psw,expected", [(0o000, 60), (0o240, 60), (0o300, 0), (0o340, 0)])
def test_interrupts_only_below_priority_6(psw, expected):
    got, ticks = count_ticks(RATE + 2500, psw=psw)
    assert (got, ticks) == (expected, 60)


def test_no_interrupts_with_ie_clear_but_monitor_set():
    prog = programs.clock_counter(enable=False)
    out = simh.run(prog.script(start=False) + f"step {RATE}\n" + examine_results(1) +
                   "examine clk lks\n")
    assert results(out, 1) == [0]
    assert simh.examined(out)["LKS"] == 0o200


def test_bad_rate_is_refused_and_kept():
    out = simh.run("set clk rate=12x\nset clk rate=0\nset clk rate=-5\nshow clk rate\n")
    assert out.count("Invalid argument") == 3
    assert "rate=300000 instructions/s" in out


def test_throttle_is_available():
    out = simh.run("set throttle 300k\nshow throttle\nset nothrottle\n")
    assert "Throttle = 300 kilocycles" in out


def test_changing_rate_mid_run_keeps_time_and_ticks_continuous():
    prog = programs.clock_counter()
    out = simh.run(prog.script(start=False) + f"step {RATE}\nset clk rate=150000\n"
                   "step 150000\nexamine clk ticks\nshow clk state\n")
    assert simh.examined(out, radix=10)["TICKS"] == 119     # the 120th lands at 2.000 s
    assert "time=2.000000s" in out


@pytest.mark.parametrize("pacing", ["set clk realtime", "set cpu idle"])
def test_wall_clock_pacing_changes_no_count(pacing):
    """SET CLK REALTIME and SET CPU IDLE pace the host (pdp11-devices/bus/kw11l.c); what
    happens at which instruction count stays the same (0.2 simulated s here)."""
    assert count_ticks(RATE // 5, extra=pacing + "\n") == count_ticks(RATE // 5)


def test_realtime_is_shown_and_can_be_ended():
    out = simh.run("set clk realtime\nshow clk\nset clk norealtime\nshow clk\n"
                   "set clk realtime=2\nshow clk\n")
    shows = [line for line in out.splitlines() if line.startswith("CLK, rate=")]
    assert [", realtime" in line for line in shows] == [True, False, False]
    assert "Non-existent parameter" in out or "Invalid argument" in out


def idle_ticks(extra=""):
    """A program that WAITs between clock interrupts (the FORTH's idle KEY): its count of
    ticks after one simulated second, and the wall seconds the run took."""
    prog = programs.idle_clock_counter()
    start = time.monotonic()
    out = simh.run(extra + prog.script(start=False) + f"step {RATE + 2500}\n" + examine_results(1))
    assert "Step expired" in out and "Non-existent" not in out and "Invalid" not in out, out
    return results(out, 1)[0], time.monotonic() - start


def test_idle_speed_paces_waits_and_changes_no_count():
    """SET CLK IDLESPEED=4 under SET CPU IDLE: a second of WAITs takes a quarter of a
    wall second at least (the clock sleeps the host), and the same 60 interrupts come."""
    plain, _ = idle_ticks()
    paced, wall = idle_ticks("set cpu idle\nset clk idlespeed=4\n")
    assert plain == paced == 60
    assert wall >= 0.2


def test_idle_speed_is_shown_and_bad_values_are_refused():
    out = simh.run("set clk idlespeed=100\nshow clk idlespeed\nset clk idlespeed=0\n"
                   "set clk idlespeed=1001\nset clk idlespeed=5x\nshow clk idlespeed\n")
    assert out.count("Invalid argument") == 3
    assert out.splitlines().count("idlespeed=100") == 2      # SHOW, before and after
