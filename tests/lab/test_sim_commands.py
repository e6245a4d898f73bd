"""The page's sim> command tables (harness/lab/sim_commands.py) against the lab's
real simulator: every device is classed, and SET's modifier tables are SIMH's own,
in SIMH's order (the order decides what an abbreviation means)."""
import re
import subprocess

from harness.lab.sim_commands import FILE_DEVICES, REGISTER_DEVICES, SETTABLE
from harness.machine.build import BUILD


def simh(*commands):
    return subprocess.run([str(BUILD / "pdp11")], input="\n".join(commands + ("quit",)) + "\n",
                          capture_output=True, text=True, timeout=30).stdout


def test_every_device_is_classed():
    devices = re.findall(r"^([A-Z][A-Z0-9]*)[,\s]", simh("show devices").split("configuration\n", 1)[1],
                         re.M)
    assert "RL" in devices and "PLANT" in devices
    unclassed = set(devices) - set(FILE_DEVICES) - set(REGISTER_DEVICES)
    assert not unclassed, f"class these devices in sim_commands.py: {sorted(unclassed)}"


def test_set_tables_are_simhs_own():
    for device, (table, _) in SETTABLE.items():
        listed = re.search(rf"^sim> {device}\t(.*)$", simh(f"show {device} modifiers"), re.M)
        assert listed, device
        assert tuple(listed.group(1).split(", ")) == table, device
