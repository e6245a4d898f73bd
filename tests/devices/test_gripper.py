"""The gripper as a PDP-11 program sees it: step pulses on DRV11 OUTBUF bit 4
(DIR bit 5), the finger contact switch on the CSR's REQ B, SET PLANT GRIPPER,
SHOW PLANT and the trace's last three columns (pdp11-devices/plant/gripper.h)."""
import csv

from programs import examine_results, results
from harness.machine import simh
from harness.machine.plant_rows import parse_show_gripper
import programs
from tests.c_unit import passes

REQB = 0o100000


def run_steps(count, close, spacing, settings=""):
    prog = programs.gripper_steps(count, close, spacing)
    out = simh.run(settings + prog.script() + examine_results(1) + "show plant\n")
    return results(out, 1)[0], parse_show_gripper(out)


def test_gripper_mechanics_unit_tests():
    assert passes("gripper_test")


def test_slow_pulses_close_the_fingers_step_by_step():
    # 2000 SOB iterations apart: 6.7 ms at 300 000 instructions/s, under 300 steps/s
    csr, g = run_steps(50, True, 2000)
    assert (g["steps"], g["pulses"], g["missed"], g["blocked"]) == (150, 50, 0, 0)
    assert g["opening"] == 1.5 and csr & REQB == 0


def test_pulses_above_the_pull_out_rate_are_missed():
    # 500 iterations apart: 1.7 ms, 600 steps/s against the motor's 300: every other one
    _, g = run_steps(60, True, 500)
    assert g["pulses"] == 60 and g["missed"] == 30 and g["steps"] == 170
    # the same pulses on a weaker motor (pull-out 100 steps/s): 5 of 6 missed
    _, g = run_steps(60, True, 500, "set plant gripper pullout=100\n")
    assert g["missed"] == 50 and g["steps"] == 190


def test_fingers_stop_on_the_object_and_the_switch_is_req_b():
    csr, g = run_steps(120, True, 2000, "set plant gripper object=1.2\n")
    assert g["steps"] == 120 and g["contact"] == 1 and g["blocked"] == 40
    assert csr & REQB


def test_closing_on_nothing_reaches_the_stop_without_contact():
    csr, g = run_steps(210, True, 2000)
    assert g["steps"] == 0 and g["contact"] == 0 and g["blocked"] == 10
    assert csr & REQB == 0


def test_bad_settings_leave_the_gripper_as_it_was():
    out = simh.run("set plant gripper object=0.5\nset plant gripper object=abc\n"
                   "set plant gripper object=2.5\nset plant gripper pullout=0\n"
                   "set plant gripper kv=3\nset plant object=1\nset plant gripper opening=0.2\n"
                   "set plant gripper\nshow plant\n")
    g = parse_show_gripper(out)
    assert (g["object"], g["steps"]) == (0.5, 200)
    assert "OBJECT needs a number" in out
    assert "OBJECT is a width in inches, 0 (none) to 2" in out
    assert "PULLOUT is a rate in steps per second" in out
    assert "KV is an axis parameter" in out
    assert "OBJECT belongs to the gripper" in out
    assert "the object is wider than that" in out
    assert "pullout 300 steps/s" in out


def test_trace_records_the_gripper(tmp_path):
    trace = tmp_path / "g.csv"
    prog = programs.gripper_steps(30, True, 2000)
    simh.run(f"set plant gripper object=1.8\nattach plant {trace}\n" + prog.script() +
             "detach plant\n")
    with open(trace, newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0])[-3:] == ["grip", "contact", "missed"]
    grips = [float(r["grip"]) for r in rows]
    assert grips[0] > 1.9 and rows[0]["contact"] == "0"
    assert grips == sorted(grips, reverse=True)            # closing, never opening
    assert grips[-1] == 1.8 and rows[-1]["contact"] == "1"


def test_a_part_is_placed_with_its_width_first():
    out = simh.run("set plant gripper partx=800\nset plant gripper object=1,partx=800,"
                   "party=800,partz=400\nset plant gripper partz=abc\nshow plant\n"
                   "set plant gripper object=0\nshow plant\n")
    assert "give the part's width first (OBJECT=width)" in out
    assert "PARTZ needs a number" in out
    shows = [parse_show_gripper(chunk) for chunk in out.split("PLANT, seed")[1:]]
    assert shows[0]["part"] == (800.0, 800.0, 400.0)       # the bad PARTZ changed nothing
    assert shows[1]["part"] is None                         # OBJECT=0 takes it away


def test_a_set_that_closes_the_contact_raises_req_b_at_once():
    """SET PLANT GRIPPER OBJECT puts an object between the fingers: the contact
    switch closes and the DRV11 (INT ENB B set) requests its interrupt there and
    then, through the hook machine_sys.c registers with the plant (the plant
    names no bus device); OBJECT=0 withdraws it."""
    out = simh.run("deposit 167770 40\nexamine drv11 intb\n"
                   "set plant gripper opening=1\nset plant gripper object=1\n"
                   "examine drv11 intb\nset plant gripper object=0\nexamine drv11 intb\n")
    assert [v for name, v in simh.examined_all(out) if name == "INTB"] == [0, 1, 0]
