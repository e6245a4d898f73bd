"""The five machines in lock-step, scripted (harness/controllers/scripted.py): two runs
of one script give byte-identical transcripts on all five consoles and one identical
plant trace, however the host schedules the five simulators and the coordinator."""
import re

from harness.controllers.coordinator import CONTROLLERS
from harness.controllers.scripted import run_five
from harness.machine import script
from harness.machine.plant_rows import AXES

# decimal addresses for the FORTH: the 11/23's links at 167760 (x), 167750, 167740,
# 167730 (CSR; OUTBUF +2, INBUF +4); on an 11/03 its link at 167760, its D/A
# channel 0 at 170440 and its counter's run line, DRV11 OUTBUF bit 0, at 167772
LINK_CSR = {a: 0o167760 - 0o10 * i for i, a in enumerate(CONTROLLERS)}
DAC0, RUN_LINE = 0o170440, 0o167772
CODES = {"x": 2100, "y": 2000, "z": 2150, "t": 2060}

MAIN_SCRIPT = "\n".join(
    [f"{1000 + i} {LINK_CSR[a] + 2} !" for i, a in enumerate(CONTROLLERS)]
    + ["#wait 0.3"]
    + [f"{LINK_CSR[a]} @ . {LINK_CSR[a] + 4} @ . {LINK_CSR[a]} @ ." for a in CONTROLLERS]
    + ["#simh show lockstep"])


def axis_lines(a):
    """Drive the axis, send the 11/23 a word, and read the link (the last line is
    typed as the machine goes free: it runs before the 11/23's word arrives)."""
    return [f"{CODES[a]} {DAC0} ! 1 {RUN_LINE} ! {CODES[a] + 1} {0o167762} !", f"{0o167764} @ ."]


def run(tmp_path, name):
    directory = tmp_path / name
    directory.mkdir()
    return run_five(script.parse(MAIN_SCRIPT), directory,
                    axis_lines={a: axis_lines(a) for a in CONTROLLERS})


def test_two_runs_are_byte_identical_and_the_plant_is_driven_by_the_11_03s(tmp_path):
    first, second = run(tmp_path, "first"), run(tmp_path, "second")
    assert not first.failures, first.failures
    assert first.transcripts == second.transcripts
    assert first.trace == second.trace
    # each 11/03 drove its own axis: a DAC row with its code, nothing else's
    rows = [r.split(",") for r in first.trace.decode().splitlines()[1:]]
    for i, a in enumerate(CONTROLLERS):
        codes = {int(r[2]) for r in rows if r[1] == AXES[i]}
        assert CODES[a] in codes, (a, codes)
    # each 11/03's word reached the 11/23's link: CSR with REQ A (128), INBUF; the
    # read clears REQ A. REQ B (bit 15) is set there exactly when the 11/03 read its
    # INBUF after the 11/23's word had arrived (it then read that word; a word the
    # 11/23 wrote afterwards would have cleared it)
    main = first.transcripts["main"]
    for i, a in enumerate(CONTROLLERS):
        csr = LINK_CSR[a]
        m = re.search(rf"^{csr} @ \. {csr + 4} @ \. {csr} @ \. (-?\d+) (\d+) (-?\d+)  ok$", main, re.M)
        before, inbuf, after = (int(g) & 0o177777 for g in m.groups())
        assert before & 0o377 == 0o200 and inbuf == CODES[a] + 1 and after & 0o377 == 0
        read = int(re.search(rf"^{0o167764} @ \. (\d+)  ok$", first.transcripts[a], re.M).group(1))
        assert read in (0, 1000 + i)
        assert bool(before & 0o100000) == (read == 1000 + i) == bool(after & 0o100000)
    assert "stopped" not in main
    assert "role=MAIN" in main
    for a in CONTROLLERS:
        assert "the 11/23 has left; the session is over" in first.transcripts[a]
