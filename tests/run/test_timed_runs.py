"""Scripted runs in 11/23 time (`run --timed`, SET CLK TIMED): deterministic, and
priced as harness/analysis/timing.py prices the same code (make bench-timed does
it on a Sieve pass)."""
import re

import pytest

from harness.bench import timed_bench
from harness.cli import main
from harness.machine.build import fresh_disk
from tests.run.common import needs_build

pytestmark = needs_build

SCRIPT = "1000 LOAD\nSet.Up.Robot\n800 800 0 0 Abs.Move Move.Complete?\n#wait 0.5\n#simh show clk\n"


def timed_run(tmp_path, name):
    script = tmp_path / "timed.script"
    script.write_text(SCRIPT)
    assert main(["run", str(script), "--timed", "--transcript", str(tmp_path / f"{name}.txt"),
                 "--trace", str(tmp_path / f"{name}.csv")]) == 0
    return (tmp_path / f"{name}.txt").read_text(), (tmp_path / f"{name}.csv").read_bytes()


def test_two_timed_runs_give_the_same_transcript_and_trace(tmp_path):
    first, second = timed_run(tmp_path, "a"), timed_run(tmp_path, "b")
    assert first == second
    assert "rate=13333333 units" in first[0]
    ticks, seconds = re.search(r"(\d+) ticks, time=([\d.]+)s", first[0]).groups()
    assert int(ticks) == int(float(seconds) * 60)      # a tick every 1/60 s of 11/23 time


def test_ticks_stay_on_the_11_23s_time_through_1000_load(tmp_path):
    """Timed, an event runs after the instruction that crosses its time, and SIMH's
    queue hands that lateness on to every event behind it: the KW11-L was once a tick
    short after `1000 LOAD` (260 in 4.35 s). Its series counts from due times now
    (time_base.c's clock_series)."""
    script = tmp_path / "load.script"
    script.write_text("1000 LOAD\n#simh show clk\n")
    assert main(["run", str(script), "--timed", "--out", str(tmp_path)]) == 0
    shown = (tmp_path / "load.transcript").read_text()
    ticks, seconds = re.search(r"(\d+) ticks, time=([\d.]+)s", shown).groups()
    assert int(ticks) == int(float(seconds) * 60) > 200


def test_a_timed_word_costs_what_timing_prices(tmp_path):
    definitions = timed_bench.DEFINITIONS[:2] + [
        ": B-PASS ( -- ) 6 PRIORITY! MARK 200 0 DO I 7 * 3 / DROP LOOP END-MARK 0 PRIORITY! ;"]
    fresh_disk(tmp_path)
    mark, end, timed = timed_bench.timed_pass(tmp_path, definitions)
    priced, instructions = timed_bench.priced_pass(tmp_path, mark, end, definitions, 20_000)
    assert instructions > 2000
    assert timed == pytest.approx(priced, rel=1e-3)           # MUL and DIV among them
    assert timed > 1.05 * instructions / 300_000              # not the count's time
