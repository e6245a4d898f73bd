"""The docs' kernel-dependent figures against a fresh run (issue 9: "add a check
that would catch the next drift"). Any kernel change moves how many instructions
boot and `1000 LOAD` take, hence when each line starts, the phase of the servo's
ticks and the free dictionary space; the docs quote those figures for the
current build, and these tests fail, naming the sentence, when a figure no
longer matches. Fix the doc (re-measure: make servo-runs, make bench-robot),
not the tolerance."""
import re
import shutil
import tempfile
from pathlib import Path

import pytest

from harness.analysis import moves, trace
from harness.analysis.tick_view import open_view
from harness.bench import servo_runs
from harness.machine.robot import numbers

ROOT = Path(__file__).resolve().parents[2]


def doc(name):
    return (ROOT / name).read_text()


def quoted(name, pattern):
    """The number a doc quotes where `pattern` (a regex with one group) matches;
    '16 474' reads as 16474."""
    text = " ".join(doc(name).split())            # sentences wrap anywhere
    found = re.search(pattern, text)
    assert found, f"{name}: no sentence matching {pattern!r}: update this test with the doc"
    return float(found.group(1).replace(" ", ""))


def test_free_bytes_and_load_time_as_documented(boot):
    """The banner's free bytes, UNUSED after 1000 LOAD and after 1040 LOAD, and
    how long boot and 1000 LOAD take, as forth/README, servo.md and
    continuation.md quote them."""
    r = boot()
    free_at_boot = int(re.search(r"(\d+) bytes free", r.banner).group(1))
    booted = r.time()
    r.send("1000 LOAD")
    loaded = r.time()
    after_1000 = numbers(r.send("UNUSED U."))[0]
    r.send("1040 LOAD")
    after_1040 = numbers(r.send("UNUSED U."))[0]

    assert quoted("forth/README.md", r"free dictionary space \(about \d+ KB: (\d+) bytes") \
        == free_at_boot
    assert quoted("forth/README.md", r"has ([\d.]+) KB free at boot") \
        == round(free_at_boot / 1000, 1)
    assert quoted("forth/README.md", r"KB free at boot, ([\d.]+) KB after `1000 LOAD`") \
        == round(after_1000 / 1000, 1)
    assert quoted("docs/continuation.md", r"([\d ]+) bytes free after `1000 LOAD 1040 LOAD`") \
        == after_1040
    assert quoted("docs/continuation.md", r"1040 LOAD`, ([\d ]+) after `1000 LOAD`\)") \
        == after_1000
    assert quoted("docs/continuation.md", r"Blocks 1040-1053 take (\d+) bytes") \
        == after_1000 - after_1040
    # times: within 0.1 s (bench-robot and this run start the clock a little apart)
    assert quoted("docs/servo.md", r"`1000 LOAD` take \(now ([\d.]+) simulated s\)") \
        == pytest.approx(loaded - booted, abs=0.1)
    assert quoted("docs/servo.md", r"`1000 LOAD`: ([\d.]+) simulated 11/23 seconds") \
        == pytest.approx(loaded - booted, abs=0.1)
    assert quoted("docs/servo.md", r"Boot and `1000 LOAD` take ([\d.]+) simulated seconds") \
        == pytest.approx(loaded, abs=0.1)
    # continuation.md names the build its path tables were measured on by this time
    assert quoted("docs/continuation.md", r"whose `1000 LOAD` takes ([\d.]+) s") \
        == pytest.approx(loaded - booted, abs=0.1)


def test_servo_doc_times_and_windows(capsys):
    """servo.md's "current build" sentence and its Reproduce windows against the
    moves run of make servo-runs (harness/servo_runs.py), made afresh."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "moves.csv"
        with servo_runs.session(path, None, "", tmp) as r:
            lines = servo_runs.run_moves(r)
        x = trace.read(path).axis("X")
    capsys.readouterr()                               # run_moves' report
    long_move = moves.find_moves(x)[0]
    at_start = long_move.first - 1                    # the row before the move
    zeroed_at = x.pos[at_start] - x.counter[at_start]
    d2_row = next(i for i in range(long_move.first, long_move.last + 1)
                  if x.dac[i] != x.dac[long_move.first])

    assert quoted("docs/servo.md", r"the long move starts at ([\d.]+) s") \
        == pytest.approx(long_move.t0, abs=0.01)
    assert quoted("docs/servo.md", r"the 150-count move's line is sent at ([\d.]+) s") \
        == pytest.approx(lines[1][0], abs=0.01)
    assert quoted("docs/servo.md", r"zeroed the x counter at position (-?\d+)") \
        == pytest.approx(zeroed_at, abs=1)
    assert quoted("docs/servo.md", r"at counter (\d+), \d+ counts before the target") \
        == x.counter[d2_row]
    # every window the page gives for this trace holds a whole move
    spans = [(m.t0, m.t1) for m in moves.find_moves(x)]
    windows = re.findall(r"printed/moves\.csv[^`]*?--window ([\d.]+):([\d.]+)", doc("docs/servo.md"))
    assert windows, "docs/servo.md: no --window on build/servo/printed/moves.csv"
    for start, end in windows:
        assert any(float(start) <= t0 and t1 <= float(end) for t0, t1 in spans), \
            f"docs/servo.md's --window {start}:{end} holds no whole move (moves: {spans})"


def test_servo_doc_tick_table(tmp_path):
    """servo.md's `python -m harness tick` example is the first table it prints."""
    text = doc("docs/servo.md")
    block = re.search(r"```\n(tick \d+, t = .*?)\n```", text, re.S)
    assert block, "docs/servo.md: no `harness tick` table"
    disk = tmp_path / "robot.dsk"
    shutil.copy(servo_runs.DISK, disk)
    robot, view = open_view(disk)
    with robot:
        assert view.step().rstrip() == block.group(1)
