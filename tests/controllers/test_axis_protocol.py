"""The link protocol's words on the 11/23 (blocks 1200-1206, docs/controllers.md
"The link protocol"): the link registers of each axis, the command words, the
errors naming the axis; without link devices (the ordinary 11/23) Set.Up.Robot
says so and loses nothing."""
import pytest

from harness.controllers.boot_lines import MAIN_BOOT_LINES
from harness.machine.build import KERNEL, PDP11, PRISTINE_DISK, fresh_disk
from harness.machine.robot import Robot

LINK_CSR = {0: 0o167760, 1: 0o167750, 2: 0o167740, 3: 0o167730}   # the contract's
CODES = {"Move.Code": 1, "Speed.Code": 2, "Reset.Code": 3, "Status.Code": 4,
         "Where.Code": 5, "Output.Code": 6, "Zero.Code": 7}


@pytest.fixture(scope="module")
def main23(tmp_path_factory):
    for need in (KERNEL, PDP11, PRISTINE_DISK):
        if not need.exists():
            pytest.fail(f"build first: {need} (make)")
    with Robot(disk=fresh_disk(tmp_path_factory.mktemp("axis-protocol")), timeout=20) as r:
        for line in MAIN_BOOT_LINES:          # the lock-step run's boot line: 1200 LOAD
            r.send(line)
        yield r


def octal(r, line):
    return r.send(f"8 BASE ! {line} DECIMAL").split()


def test_each_axis_has_its_link_registers(main23):
    for axis, csr in LINK_CSR.items():
        assert octal(main23, f"{axis} Link U.  {axis} Link 2+ U.  {axis} Link 4 + U.") == \
            [f"{csr:o}", f"{csr + 2:o}", f"{csr + 4:o}"]


def test_command_words_are_122400_plus_code(main23):
    for name, code in CODES.items():
        assert octal(main23, f"Command {name} OR U.") == [f"{0o122400 + code:o}"]


def test_link_errors_name_the_axis(main23):
    main23.send(': LOST ( axis -- ) C" 11/03 axis ? stopped" Axis.Error ;')
    for axis, letter in enumerate("xyzt"):
        ok, out, error = main23.reply(f"{axis} LOST")
        assert not ok and error == f"11/03 axis {letter} stopped: LOST"
    assert main23.send("1 Axis.Name 3 Axis.Name") == "yt"


def test_set_up_robot_without_links_says_so(main23):
    ok, out, error = main23.reply("7 8 9 Set.Up.Robot")
    assert not ok
    assert error == "no link DRV11 to axis x: CONTROLLERS=4 runs them: Set.Up.Robot"
    assert main23.send("DEPTH .  Desire.Pos ?") == "0 0 "   # words intact, nothing sent
