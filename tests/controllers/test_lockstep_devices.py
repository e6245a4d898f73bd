"""The lock-step's devices at the bus, with machine code deposited by SIMH (no FORTH):
two simulators (the 11/23 as MAIN, an 11/03 as X) joined to build/lockstep-coordinator.
pdp11-devices/bus/link_dev.c and simh/lockstep_dev.c say what they implement."""
import json
import subprocess

import pytest

from harness.controllers.coordinator import Coordinator, member_settings
from harness.machine.build import MACHINE_INI, PDP11
from harness.machine.simh import deposit, examined

# 11/23: MOV #12345,@#167762 ; 1$: TSTB @#167760 ; BPL 1$ ; MOV @#167764,R1 ; HALT
MAIN_SENDS = [0o012737, 0o012345, 0o167762, 0o105737, 0o167760, 0o100375,
              0o013701, 0o167764, 0o000000]
# 11/03: MOV #1,@#167772 (run line) ; MOV #3000,@#170440 (DAC ch 0) ;
# 1$: TSTB @#167760 ; BPL 1$ ; MOV @#167764,R0 ; INC R0 ; MOV R0,@#167762 ;
# 2$: MOV @#167774,R2 ; BR 2$        (counter, for ever)
AXIS_ECHOES = [0o012737, 0o000001, 0o167772, 0o012737, 0o003000, 0o170440,
               0o105737, 0o167760, 0o100375, 0o013700, 0o167764, 0o005200,
               0o010037, 0o167762, 0o013702, 0o167774, 0o000775]


def start(member, socket, program, after, directory, name):
    """`program` at 1000, run until it halts; or, if it is `BR .`, for 3000 instructions."""
    run = "deposit pc 1000\nstep 3000\n" if program == [0o000777] else "go 1000\n"
    script = (f"do {MACHINE_INI}\n" + "".join(f"{c}\n" for c in member_settings(member, socket))
              + deposit(0o1000, program) + run + after + "quit\n")
    path = directory / f"{name}.ini"
    path.write_text(script)
    return subprocess.Popen([str(PDP11), str(path)], stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def run_pair(tmp_path, main_program, main_after, axis_program, axis_after):
    with Coordinator(tmp_path, trace="trace.csv", members=("x", "main"),
                     status=tmp_path / "status.json") as c:
        axis = start("x", c.socket, axis_program, axis_after, tmp_path, "x")
        main = start("main", c.socket, main_program, main_after, tmp_path, "main")
        main_out, _ = main.communicate(timeout=60)
        axis_out, _ = axis.communicate(timeout=60)
        status, said = c.wait()
    return main_out, axis_out, status, said, (tmp_path / "trace.csv").read_text()


def test_a_word_crosses_the_link_both_ways_and_the_axis_moves(tmp_path):
    main_out, axis_out, status, said, trace = run_pair(
        tmp_path, MAIN_SENDS, "examine r1\nexamine 17767760\n",
        AXIS_ECHOES, "examine r0\nexamine r2\nexamine 17767760\n")
    assert status == 0, said
    main, axis = examined(main_out), examined(axis_out)
    assert main["R1"] == 0o12346, main_out                # the 11/03's answer, + 1
    assert main["17767760"] == 0o100000, main_out         # REQ B: the 11/03 took the word
    assert axis["R0"] == 0o12346                          # it read 12345
    assert axis["17767760"] == 0                          # REQ A cleared by its read
    assert "the 11/23 has left; the session is over" in axis_out
    # the 11/03's D/A channel 0 drives axis x: its write is a trace row, and x's
    # counter (its own, no multiplexer) ran while the 11/03 read it
    assert any(row.split(",")[1:3] == ["X", str(0o3000)] for row in trace.splitlines()[1:])
    assert axis["R2"] != 0 and axis["R2"] > 0o100000      # moving down: a negative count
    # the coordinator's status (the lab's page): both words, the 11/03 x lost at the end
    status = json.loads((tmp_path / "status.json").read_text())
    x = status["axes"][0]
    assert [w for _, w in x["to_11_03"]] == [0o12345] and [w for _, w in x["to_11_23"]] == [0o12346]
    assert status["members"]["y"] == "absent"


def test_a_lost_11_03_sets_peer_lost_and_is_reported_on_the_11_23(tmp_path):
    # the 11/03 halts at once and quits; the 11/23 runs on without it
    main_out, _, status, said, _ = run_pair(
        tmp_path, [0o000777], "examine 17767760\n", [0o000000], "")   # BR . ; HALT
    assert status == 0
    assert "x lost" in said
    assert "11/03 axis x stopped: its simulator is gone (link x CSR bit 8 set)" in main_out
    assert examined(main_out)["17767760"] & 0o400


def test_main_without_an_11_03_joined_runs_on_and_says_so_once(tmp_path):
    main_out, _, _, _, _ = run_pair(tmp_path, [0o000777], "", [0o000000], "")
    assert main_out.count("11/03 axis x stopped") == 1


@pytest.mark.parametrize("command, refusal", [
    ("attach lockstep /nonexistent/sock", "SET LOCKSTEP ROLE=... first"),
    ("set lockstep role=W", "ROLE is X, Y, Z, T"),
])
def test_bad_lockstep_commands_say_why(command, refusal):
    from harness.machine import simh
    out = simh.run(command + "\n")
    assert refusal in out


def test_the_ordinary_machine_has_no_links():
    from harness.machine import simh
    out = simh.run("show lockstep\nshow link0\nexamine 17767760\n")
    assert "role=none" in out
    assert "LINK0, disabled" in out
    assert "17767760" not in simh.examined(out)            # nothing answers at 167760
