"""Pricing executed code from SIMH's CPU history, on hand-assembled programs
whose cost is worked out here by hand from docs/kdf11-timing.md (MMU off)."""
import pytest

from harness.analysis import kdf11, timing
from harness.analysis.pdp11prog import Program
from harness.analysis.timing import TimingError, price_spans
from servo_program import servo_program
from timing_programs import CALL_US, HANDLER_US, call_program, counting_handler

def test_interrupt_handler_per_execution_and_per_tick():
    report = timing.measure(counting_handler().script(start=False), entry=0o1400,
                            instructions=50_000)
    assert report.ticks >= 9 and report.count == report.ticks   # once per tick
    assert all(s.instructions == 4 and s.interrupt_entry for s in report.spans)
    assert [s.microseconds for s in report.spans] == pytest.approx([HANDLER_US] * report.count)
    assert report.per_tick_us == pytest.approx(HANDLER_US)
    assert report.percent_of_tick == pytest.approx(100 * HANDLER_US / (1e6 / 60))
    n = report.count
    assert report.by_mnemonic["MOV"] == pytest.approx([2 * n, (3.75 + 3.0) * n])
    assert report.by_mnemonic["INC"] == pytest.approx([n, 5.625 * n])
    assert report.by_mnemonic["(interrupt entry)"] == pytest.approx([n, kdf11.INTERRUPT_ENTRY * n])
    assert report.rate == 300_000 and report.instructions_run == 50_000
    text = report.format("counter")
    assert "per 60 Hz tick: 27.300 us" in text and "estimate" in text


def test_vector_names_the_handler():
    """(Spans cut between history chunks: tests/harness/test_timing_reader.py.)"""
    report = timing.measure(counting_handler().script(start=False), vector=0o100,
                            instructions=10_000)
    assert report.entry == 0o1400
    assert report.count >= 1 and report.mean_us == pytest.approx(HANDLER_US)


def test_straight_code_through_a_stop_address():
    setup = call_program().script(start=False)
    report = timing.measure(setup, entry=0o1000, end=0o1010, instructions=200)
    (span,) = report.spans
    assert (span.instructions, span.interrupt_entry) == (8, False)
    assert span.microseconds == pytest.approx(CALL_US)
    assert report.by_mnemonic["SOB"] == pytest.approx([5, 4 * 2.7 + 2.4])


def test_servo_hold_path_priced_by_hand():
    """The hand servo's cheapest path: x in range, held at ZERO (9 instructions)."""
    report = timing.measure(servo_program().script(start=False), vector=0o100,
                            instructions=30_000)
    hold = 4.2 + 4.2 + 1.8 + 1.8 + 4.2 + 1.8 + 6.9 + 4.5 + 5.55 + 9.375   # 44.325
    nine = [s.microseconds for s in report.spans if s.instructions == 9]
    assert nine and nine == pytest.approx([hold] * len(nine))
    assert min(s.microseconds for s in report.spans) == pytest.approx(hold)


def test_a_run_that_halts_is_reported_and_stops_there():
    p = Program()
    p.mov_imm_reg(5, 0).sob_self(0).halt()
    # chunks of 100: the later steps run on past the HALT; their history is ignored
    report = timing.measure(p.script(start=False), entry=0o1000, end=0o1004,
                            instructions=1000, chunk=100)
    assert report.stopped == "HALT instruction at PC 001010"
    assert report.total_us == pytest.approx(3.0 + 2.7)       # MOV, the first SOB
    with pytest.raises(TimingError, match="the run stopped: HALT instruction"):
        timing.measure(p.script(start=False), entry=0o1000, end=0o1010,
                       instructions=1000, chunk=100)


def test_measure_errors():
    setup = call_program().script(start=False)
    with pytest.raises(TimingError, match="never ran through 001010"):
        timing.measure(setup, entry=0o1002, end=0o1010, instructions=100)
    with pytest.raises(TimingError, match="chunk"):
        timing.measure(setup, entry=0o1000, chunk=10)
    with pytest.raises(TimingError, match="one of them"):
        timing.measure(setup, entry=0o1000, vector=0o100)


def history(*lines):
    """SHOW CPU HISTORY text as price_spans() reads it: a piece a line."""
    return [line + "\n" for line in lines]


def test_sob_priced_from_its_source_register():
    """SOB is taken unless R was 1 (the src column); the PSW's priority and the
    disassembly are read from their own columns."""
    words = {0o1004: 0o077001}                             # SOB R0,1004
    report = price_spans(history("001004 000000|000003 000001  SOB R0,1004",
                                 "001004 000340|000001 000000  SOB R0,1004"),
                         words, 0o1004, end=0o1004)
    assert [s.interrupt_entry for s in report.spans] == [False, True]
    assert [s.microseconds for s in report.spans] == [
        kdf11.SOB_TAKEN, kdf11.SOB_NOT_TAKEN + kdf11.INTERRUPT_ENTRY]


def test_price_spans_detects_changed_code_and_counts_unfinished():
    words = {0o1000: 0o005001, 0o1002: 0o000002}          # CLR R1, RTI
    run = history("001000 000000|       000000  CLR R1",
                  "001002 000000|               RTI",
                  "001000 000000|       000000  CLR R1")
    report = price_spans(run, words, 0o1000)
    assert report.count == 1 and report.incomplete == 1
    assert report.total_us == pytest.approx(1.8 + 5.55)
    with pytest.raises(TimingError, match="the code changed"):
        price_spans(run, {0o1000: 0o005201, 0o1002: 0o000002}, 0o1000)   # INC R1 now


def test_interrupt_entry_charged_after_a_priority_rise_not_after_a_trap():
    words = {0o1000: 0o104400, 0o1014: 0o000777, 0o1400: 0o000002}   # TRAP 0, BR ., RTI
    trapped = price_spans(history("001000 000000|               TRAP 0",
                                  "001400 000340|               RTI"), words, 0o1400)
    interrupted = price_spans(history("001014 000000|               BR 1014",
                                      "001400 000340|               RTI"), words, 0o1400)
    assert [s.interrupt_entry for s in trapped.spans] == [False]
    assert trapped.total_us == pytest.approx(5.55)
    assert [s.interrupt_entry for s in interrupted.spans] == [True]
    assert interrupted.total_us == pytest.approx(5.55 + kdf11.INTERRUPT_ENTRY)
