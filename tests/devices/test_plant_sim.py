"""The four-axis plant as a PDP-11 program sees it through the AAV11-A and DRV11,
in simulated time (build/pdp11), against closed-form answers."""
import math

import pytest

from programs import examine_results, results
from harness.machine import simh
from plantio import AXES, QUIET, show_rows, read_trace
import programs

RATE = 300000
TAU = dict(X=0.020, Y=0.020, Z=0.015, T=0.010)
AMAX = dict(X=160000, Y=160000, Z=120000, T=160000)
PMIN = dict(X=-9600, Y=-7200, Z=-4000, T=-12000)
PMAX = dict(X=9600, Y=7200, Z=2400, T=12000)
OFFSET = dict(X=3.0, Y=-2.0, Z=45.0, T=0.6)
KV = 19.53


def traced_run(tmp_path, codes, seconds, settings="", sample=1000, name="trace.csv"):
    trace = tmp_path / name
    prog = programs.dac_step(codes)
    out = simh.run(settings + f"set plant sample={sample}\nattach plant {trace}\n" +
                   prog.script(start=False) + f"step {int(seconds * RATE)}\n"
                   "show plant\ndetach plant\n")
    return out, read_trace(trace)


def test_step_response_matches_the_first_order_lag(tmp_path):
    codes = [2148, 2148, 2148, 2120]          # every step well under amax * tau
    out, rows = traced_run(tmp_path, codes, 0.25, QUIET)
    for axis, code in zip(AXES, codes):
        mine = [r for r in rows if r["axis"] == axis]
        start = next(r for r in mine if r["dac"] == code)
        vc, v0, p0, t0 = start["vcmd"], start["vel"], start["pos"], start["t"]
        assert vc == pytest.approx(KV * (code - 2048 - OFFSET[axis]), abs=1e-3)
        assert abs(vc - v0) < AMAX[axis] * TAU[axis]      # away from the current limit
        later = [r for r in mine if r["t"] > t0]
        assert len(later) >= 200
        for r in later:
            dt, tau = r["t"] - t0, TAU[axis]
            v = vc + (v0 - vc) * math.exp(-dt / tau)
            p = p0 + vc * dt + (v0 - vc) * tau * (1 - math.exp(-dt / tau))
            assert abs(r["vel"] - v) <= 0.01 * abs(vc - v0), (axis, r)
            assert abs(r["pos"] - p) <= 0.01 * max(abs(p - p0), 1.0), (axis, r)


def test_acceleration_limit_holds(tmp_path):
    out, rows = traced_run(tmp_path, [4095] * 4, 0.3, QUIET)
    for axis in AXES:
        mine = [r for r in rows if r["axis"] == axis]
        rates = [(b["vel"] - a["vel"]) / (b["t"] - a["t"]) for a, b in zip(mine, mine[1:])
                 if b["t"] - a["t"] > 1e-4 and PMIN[axis] < b["pos"] < PMAX[axis]]
        assert max(rates) <= AMAX[axis] * 1.0001 + 5, axis
        assert max(rates) >= AMAX[axis] * 0.99, axis


def test_end_stops_hold(tmp_path):
    out, rows = traced_run(tmp_path, [4095] * 4, 1.0)
    up = show_rows(out)
    out2, rows2 = traced_run(tmp_path, [0] * 4, 2.0, name="down.csv")
    down = show_rows(out2)
    for axis in AXES:
        assert (up[axis]["pos"], up[axis]["vel"], up[axis]["stop"]) == (PMAX[axis], 0.0, "upper")
        assert (down[axis]["pos"], down[axis]["vel"], down[axis]["stop"]) == (PMIN[axis], 0.0, "lower")
    assert all(PMIN[r["axis"]] <= r["pos"] <= PMAX[r["axis"]] for r in rows + rows2)


def test_counters_wrap_and_clear_and_hold_on_their_run_line():
    prog = programs.counter_wrap()
    settings = "set plant t offset=0,walk=0,pmax=200000\n"
    out = simh.run(settings + prog.script() + examine_results(1) + "show plant\n"
                   "go\n" + examine_results(4))
    assert out.count("HALT instruction") == 2
    first = simh.examined_all(out)
    pos = show_rows(out)["T"]["pos"]
    assert pos > 65536                               # far enough to wrap
    assert first[0] == ("2000", math.floor(pos) % 65536)
    r = results(out, 4)
    assert r[1] == 0 and r[2] == 0                  # run line 0: cleared and held
    count = r[3] - 65536 if r[3] & 0o100000 else r[3]
    assert -2200 < count < -1500                     # counts again, down, two's complement


def test_code_2048_drifts_at_kv_times_offset():
    prog = programs.dac_step([2048] * 4)
    out = simh.run(QUIET + prog.script(start=False) + f"step {RATE}\nshow plant\n")
    rows = show_rows(out)
    for axis in AXES:
        assert rows[axis]["vel"] == pytest.approx(-KV * OFFSET[axis], abs=1e-3)
        assert rows[axis]["offset"] == OFFSET[axis]


def test_same_program_same_trace_byte_for_byte(tmp_path):
    codes = [2300, 1800, 2090, 2600]
    traced_run(tmp_path, codes, 2.001, sample=60, name="a.csv")
    traced_run(tmp_path, codes, 2.001, sample=60, name="b.csv")
    traced_run(tmp_path, codes, 2.001, "set plant seed=7\n", sample=60, name="c.csv")
    a, b, c = ((tmp_path / n).read_bytes() for n in ("a.csv", "b.csv", "c.csv"))
    assert a.startswith(b"time_s,axis,dac,vcmd,vel,pos,counter,grip,contact,missed\n")
    assert len(a.splitlines()) == 1 + 4 * 120 + 4        # header, samples, the program's writes
    assert a == b
    assert a != c                                     # the walk follows the seed


def test_bad_set_and_attach_leave_the_plant_as_it_was(tmp_path):
    bad = ["set plant w tau=20", "set plant q", "set plant x tau=0", "set plant x tau=-3",
           "set plant x tau=abc", "set plant x kv=", "set plant tau=20",
           "set plant z pmin=3000", "set plant y pos=99999", "set plant sample=5000",
           "set plant seed=-1", "set plant x offset=1e400", "set plant t vmax=nan",
           f"attach plant {tmp_path}/no/such/dir/t.csv"]
    out = simh.run("show plant\n" + "\n".join(bad) + "\nshow plant\n")
    shows = [chunk.split("\n") for chunk in out.split("PLANT, ")[1:]]
    assert len(shows) == 2
    first, second = ([shows[i][0]] + [l for l in shows[i][1:11] if l.startswith("  ")]
                     for i in range(2))
    assert len(first) == 11 and first == second
    errors = [l for l in out.splitlines() if l in ("Invalid argument", "Non-existent parameter",
                                                   "Missing value", "File open error")]
    assert len(errors) == len(bad)
    assert "cannot write the trace" in out
    assert "not attached" in second[0]


def test_show_devices_lists_the_robot_devices():
    out = simh.run("show devices\n")
    names = [l.split(",")[0] for l in out.splitlines()]
    for dev in ("CLK", "DRV11", "AAV11", "PLANT", "RL", "TTI", "TTO"):
        assert dev in names
    assert "CLK, rate=300000 instructions/s" in out
    assert "DRV11, CSR=000000" in out and "vector=300-304" in out


def test_sample_0_traces_dac_writes_only(tmp_path):
    out, rows = traced_run(tmp_path, [2148, 2048, 2048, 1948], 0.5, sample=0)
    assert [(r["axis"], r["dac"]) for r in rows] == [("X", 2148), ("Y", 2048), ("Z", 2048),
                                                     ("T", 1948)]
    assert all(r["t"] < 1e-4 for r in rows)


def test_a_move_waiting_on_the_rack_switched_off_is_told_once(tmp_path):
    """SET PLANT HINT=ON (make run's console: rack_hint.c): with the rack off, a move
    the servo commands for 2 simulated seconds gets one line at the console; the
    machine's run is the same, hint or not (the plant trace byte for byte); with
    the hint off (scripted runs) or the rack on, no line."""
    from harness.machine.build import KERNEL, fresh_disk
    from harness.machine.console_session import boot_script

    def run(name, settings):
        trace = tmp_path / f"{name}.csv"
        out = simh.run(f"attach rl0 {fresh_disk(tmp_path, name + '.dsk')}\n{settings}"
                       f"attach plant {trace}\nload {KERNEL}\nstep 6000000\ndetach plant\n",
                       keyboard="1000 LOAD\rSet.Up.Robot\r800 800 400 0 Abs.Move\r", timeout=120)
        return out, trace.read_bytes()
    told, told_trace = run("told", "set plant power=off\nset plant hint=on\n")
    quiet, quiet_trace = run("quiet", "set plant power=off\n")
    on, _ = run("on", "set plant hint=on\n")
    line = "[plant] The amplifier rack is OFF: the servo has commanded axis X to move for 2 s"
    assert told.count(line) == 1 and "Move.Complete? waits for ever" in told
    assert line not in quiet and line not in on
    assert told_trace == quiet_trace
    assert "set plant hint=on" in boot_script(tmp_path / "d.dsk")       # make run's console
