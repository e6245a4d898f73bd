"""SET PLANT and SHOW PLANT at a member's sim> act on the one plant the lock-step
coordinator steps (pdp11-devices/simh/lockstep_dev.c, plant/plant_dev.c,
lockstep/quantum.c): two simulators with machine code deposited by SIMH (no
FORTH), the 11/03 of x driving its D/A, the 11/23 switching the rack off and on
at its sim> between STEPs, the 11/03 setting y's offset at its own. The long FORTH run of the five machines is
test_five_plant_long.py (make test-controllers-long)."""
import csv
import io
import json
import re
import subprocess

from harness.controllers.coordinator import Coordinator, member_settings
from harness.lab.controllers_page import read_view
from harness.machine.build import MACHINE_INI, PDP11
from harness.machine.simh import deposit

# 11/03 x: MOV #1,@#167772 (counter runs) ; MOV #3000,@#170440 (D/A channel 0: code 1536,
# x moves down) ; BR .
AXIS_DRIVES = [0o012737, 0o000001, 0o167772, 0o012737, 0o003000, 0o170440, 0o000777]
BR_DOT = [0o000777]
OFF_AT, ON_AFTER = 3000, 60000          # 11/23 instructions: 10 ms, then 200 ms (300 000 a second)

MAIN_SIM = f"""set plant sample=1000
deposit pc 1000
step {OFF_AT}
set plant power=off
show plant
set plant x tau=-5
set plant gripper object=1
set plant hint=on
attach plant elsewhere.csv
step {ON_AFTER}
show plant
set plant power=on
step {ON_AFTER}
quit
"""


# the 11/03's sim> sets another axis of the one plant: y's amplifier offset
AXIS_SIM = """deposit pc 1000
step 1500
set plant y offset=-40
cont
show plant
quit
"""


def simulator(member, socket, program, commands, directory):
    script = (f"do {MACHINE_INI}\n" + "".join(f"{c}\n" for c in member_settings(member, socket))
              + deposit(0o1000, program) + commands)
    (directory / f"{member}.ini").write_text(script)
    return subprocess.Popen([str(PDP11), str(directory / f"{member}.ini")], cwd=directory,
                            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)


def run(directory):
    with Coordinator(directory, trace="trace.csv", members=("x", "main"),
                     status=directory / "status.json") as c:
        axis = simulator("x", c.socket, AXIS_DRIVES, AXIS_SIM, directory)
        main = simulator("main", c.socket, BR_DOT, MAIN_SIM, directory)
        main_out, _ = main.communicate(timeout=60)
        axis_out, _ = axis.communicate(timeout=60)
        status, said = c.wait()
    assert status == 0, said
    return main_out, axis_out, (directory / "trace.csv").read_text()


def x_rows(trace):
    return [r for r in csv.DictReader(io.StringIO(trace)) if r["axis"] == "X"]


def test_the_rack_switched_at_the_11_23s_sim_stops_and_resumes_the_drive(tmp_path):
    main_out, axis_out, trace = run(tmp_path)
    shows = main_out.split("PLANT, ")[1:]
    # SHOW at the 11/23 is the coordinator's plant: x's D/A holds what 11/03 x wrote
    # (1536; the 11/23's own plant would say 2048); the SET typed at this sim> is
    # shown as it will be from the next boundary, then as it is
    assert "power=off" in shows[0] and "the SETs typed since shown" in shows[0]
    assert "power=off" in shows[1] and "SETs typed since" not in shows[1]
    assert " 1536 " in shows[1].split("\n  X ")[1].split("\n")[0]
    # bad settings say why in one line and change nothing
    assert "PLANT X: TAU (ms) must be positive" in main_out
    assert "PLANT: no gripper among the five machines" in main_out
    assert "PLANT: no HINT among the five machines" in main_out
    assert "PLANT: among the five machines the trace is the coordinator's" in main_out
    assert not (tmp_path / "elsewhere.csv").exists()
    assert "TAU(ms)" in shows[1] and "\n  X     19.53     20 " in shows[1]
    # the trace: SAMPLE=1000 took effect at the first boundary (a row each ms);
    # the drive (vcmd) stops at one boundary and comes back exactly 200 ms later
    rows = x_rows(trace)
    assert sum(1 for r in rows if 0.1 < float(r["time_s"]) <= 0.2) == 100
    off = [float(r["time_s"]) for r in rows if float(r["vcmd"]) == 0]
    assert off, "the drive never stopped"
    t_off, t_last_off = off[0], off[-1]
    assert abs(t_off * 1000 - round(t_off * 1000)) < 1e-9        # at a boundary
    assert 0.009 < t_off < 0.013
    assert len(off) == 200 and abs(t_last_off - t_off - 0.199) < 1e-9
    at = {round(float(r["time_s"]), 6): r for r in rows}
    drive = 19.53 * (1536 - 2048 - 3)                             # x's KV, code, offset
    assert abs(float(at[round(t_off - 0.001, 6)]["vcmd"]) - drive) < 1
    assert abs(float(at[round(t_off + 0.150, 6)]["vel"])) < 1     # at rest with the rack off
    assert abs(float(at[round(t_off + 0.200, 6)]["vcmd"]) - drive) < 1   # on again
    assert float(at[round(t_off + 0.300, 6)]["vel"]) < -9000      # and moving
    # the 11/03 sees the same plant: its SHOW at the end says the rack is on; its SET
    # of y's offset (at 5 ms of its time) reached the 11/23's SHOW and y's drive
    assert "power=on" in axis_out.split("PLANT, ")[-1]
    assert re.search(r"\n  Y .* -40\.0\d\d -  ", shows[0])
    y = [r for r in csv.DictReader(io.StringIO(trace)) if r["axis"] == "Y"]
    y_drive = {round(float(r["time_s"]), 3): float(r["vcmd"]) for r in y}
    assert abs(y_drive[0.004] - 19.53 * 2) < 1 and abs(y_drive[0.006] - 19.53 * 40) < 1
    # the coordinator's status says the rack's state, and the lab's page of the five shows it
    status_file = tmp_path / "status.json"
    status = json.loads(status_file.read_text())
    assert status["power"] == 1 and read_view(status_file, tmp_path)["rack_on"] is True
    status_file.write_text(json.dumps({**status, "power": 0}))
    assert read_view(status_file, tmp_path)["rack_on"] is False
