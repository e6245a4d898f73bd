"""The gripper words of blocks 1044 and 1053 (the project's continuation),
stepping the gripper from the 60 Hz interrupt (Interrupt.Path) one pulse a
tick, against the plant's gripper (pdp11-devices/plant/gripper.h): 100 steps an
inch, fully open at power-up, pull-out rate 300 steps/s, a finger switch on
DRV11 REQ B. Measured: Close.Gripper gives 220 pulses (200 and 20 onto the
stop), one a tick; a 1-inch object stops the fingers at 1.00 in and Grasp says
true, while the FORTH's own count (Grip.Pos) says 0.80 in: the steps given
into the object are lost, and Open.Gripper counts afresh from the open stop;
a grasp of nothing ends at 0.80 in and says false; two pulses a tick come 30
us apart, far above the pull-out rate, and every second one is missed."""
import pytest

from continuation import load


def gripper(r):
    g = r.gripper()
    return {k: g[k] for k in ("opening", "contact", "pulses", "missed", "blocked")}


@pytest.fixture
def robot(boot):
    r = load(boot, trace=False)
    r.send("Path.Servo")
    return r


def test_close_open_grasp_and_grasp_of_nothing(robot):
    robot.send("Close.Gripper")
    assert gripper(robot) == dict(opening=0.0, contact=0, pulses=220, missed=0, blocked=20)
    robot.send("Open.Gripper")
    g = gripper(robot)
    assert (g["opening"], g["pulses"], g["blocked"]) == (2.0, 440, 40)
    assert robot.send("Grip.Pos ?").split() == ["200"]
    # a 1-inch part: held, and the count is lost until the next Open.Gripper
    robot.simh("set plant gripper object=1")
    assert robot.send("100 Grasp .").split() == ["-1"]
    g = gripper(robot)
    assert (g["opening"], g["contact"], g["blocked"]) == (1.0, 1, 60)
    assert robot.send("Grip.Pos ? Holding? .").split() == ["80", "-1"]
    robot.send("Open.Gripper")
    assert gripper(robot)["opening"] == 2.0 and gripper(robot)["contact"] == 0
    assert robot.send("Grip.Pos ? Holding? .").split() == ["200", "0"]
    # the part taken away: a grasp of nothing
    robot.simh("set plant gripper object=0")
    assert robot.send("100 Grasp .").split() == ["0"]
    g = gripper(robot)
    assert (g["opening"], g["contact"], g["missed"]) == (0.8, 0, 0)


def test_steps_too_fast_are_missed(robot):
    robot.send("2 Grip.Rate ! Close.Gripper 1 Grip.Rate !")
    g = gripper(robot)
    assert g["pulses"] == 220 and g["missed"] == 110        # every second one
    assert g["opening"] == pytest.approx(0.9)               # the FORTH believes 0
    assert robot.send("Grip.Pos ?").split() == ["0"]
    # a weak motor (pull-out 40 steps/s) at one pulse a tick (60 steps/s)
    robot.send("Open.Gripper")
    robot.simh("set plant gripper pullout=40")
    before = gripper(robot)["missed"]
    robot.send("Close.Gripper")
    g = gripper(robot)
    assert g["missed"] - before == 110 and g["opening"] == pytest.approx(0.9)
