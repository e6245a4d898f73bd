"""The scripted runs' stop at the prompt (pdp11-devices/simh/prompt_cue.c): the CUE
device stops the simulator exactly where a SIMH breakpoint on the same address
does, so transcripts, plant traces and instruction counts are the same; and it
stops only there."""
from harness.machine.build import fresh_disk
from harness.machine.scripted_machine import ScriptedMachine
from tests.run.common import needs_build

pytestmark = needs_build

# lines that move the robot (the trace depends on each line's instruction count),
# wait, fail, and read KEY? and the receiver status (RCSR) elsewhere than at the cue
LINES = ["1000 LOAD", "Set.Up.Robot", "800 800 0 0 Abs.Move", "NO-SUCH-WORD",
         "KEY? . 177560 @ .", "Move.Complete?"]


def session(tmp_path, name, **options):
    work = tmp_path / name
    work.mkdir()
    disk = fresh_disk(work)
    with ScriptedMachine(disk.name, trace="trace.csv", cwd=work, **options) as m:
        out = [m.boot_output] + [m.line(text).output for text in LINES]
        out.append(m.wait(0.5).output)
        out += [m.simh("show clk"), m.simh("examine cue stops")]
    return out, (work / "trace.csv").read_text()


def stops(examined):
    name, count = examined.split()
    return int(count) if name == "STOPS:" else None


def test_the_cue_stops_where_a_breakpoint_on_it_does(tmp_path):
    by_device, trace = session(tmp_path, "device")
    by_breakpoint, breakpoint_trace = session(tmp_path, "breakpoint", cue_breakpoint=True)
    assert "Error: undefined word: NO-SUCH-WORD" in by_device[4]
    assert by_device[:-1] == by_breakpoint[:-1] and trace == breakpoint_trace
    assert "time=" in by_device[-2]
    assert stops(by_device[-1]) == 1 + len(LINES)        # the boot and every line
    assert stops(by_breakpoint[-1]) == 0
