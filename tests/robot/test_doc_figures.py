"""The docs' kernel-dependent figures against a fresh run (issue 9: "add a check
that would catch the next drift"). Any kernel change moves how many instructions
boot and `1000 LOAD` take, hence when each line starts, the phase of the servo's
ticks and the free dictionary space; the docs quote those figures for the
current build, and these tests fail, naming the sentence, when a figure no
longer matches. Fix the doc (re-measure: make servo-runs, make bench-robot),
not the tolerance."""
import re
import tempfile
from pathlib import Path

import pytest

from harness.analysis import moves, trace
from harness.analysis.tick_view import open_view
from harness.figures import servo_runs
from harness.machine.build import fresh_disk
from harness.machine.robot import numbers

ROOT = Path(__file__).resolve().parents[2]


def doc(name):
    return (ROOT / name).read_text()


def sentence(name, pattern):
    """What `pattern`'s one group matches in a doc (sentences wrap anywhere)."""
    text = " ".join(doc(name).split())
    found = re.search(pattern, text)
    assert found, f"{name}: no sentence matching {pattern!r}: update this test with the doc"
    return found.group(1)


def quoted(name, pattern):
    """The number a doc quotes where `pattern` matches; '16 474' reads as 16474."""
    return float(sentence(name, pattern).replace(" ", ""))


def tick_view(tmp_path, **lines):
    """`python -m harness tick`'s view (harness/analysis/tick_view.py) on a disk copy."""
    return open_view(fresh_disk(tmp_path), **lines)


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
    robot, view = tick_view(tmp_path)
    with robot:
        assert view.step().rstrip() == block.group(1)


def test_exercise_hunting_codes(tmp_path):
    """docs/exercises.md's answer 3 quotes x's DAC codes over one hunting period
    as `python -m harness tick --ticks 16 --line "800 0 400 0 Abs.Move
    Move.Complete?"` shows them."""
    codes = [int(c) for c in sentence(
        "docs/exercises.md", r"(?:Four|Five) ticks on x after a 1-inch move \(([\d, ]+), \.\.\.\)").split(",")]
    robot, view = tick_view(tmp_path, watch=("800 0 400 0 Abs.Move Move.Complete?",))
    with robot:
        shown = []
        for _ in range(16):
            view.step()
            shown.append(robot.plant()["X"]["dac"])
    assert any(shown[i:i + len(codes)] == codes for i in range(len(shown))), \
        f"docs/exercises.md's codes {codes} are not in x's DAC column {shown}"
