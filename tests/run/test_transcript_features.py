"""Pure parts of scripted runs: the transcript's line ends around SIMH
exchanges, and expected trace features (read, check, update)."""
import pytest

from harness.analysis.trace_features import FeatureError, check, read_expected, update_expected
from harness.machine.script_run import Transcript


def test_a_late_lf_after_a_simh_exchange_is_not_doubled():
    t = Transcript()
    t.console("\r\nbanner\r\n ok\r")            # the LF still in the transmitter
    t.simh("show clk", "CLK, rate=300000\r\n")
    t.console("\n1 . 1  ok\r")                 # ... arrives with the next output
    assert t.text() == "\nbanner\n ok\nsim> show clk\nCLK, rate=300000\n1 . 1  ok\n"


def test_console_output_split_across_stops_joins():
    t = Transcript()
    t.console(" ok\r")
    t.console("\n2 . 2  ok\r")
    assert t.text() == " ok\n2 . 2  ok\n"


FEATURES = """# comment line
final_counter  X   800   5   # within Range
duration       -   1.5   0.1
"""


def test_features_checked_with_tolerances():
    expected = read_expected(FEATURES)
    assert check({("final_counter", "X"): 804.0, ("duration", "-"): 1.45}, expected) == []
    assert check({("final_counter", "X"): 806.0}, expected) == [
        "final_counter X: measured 806.000, expected 800 +- 5",
        "duration -: not in the trace"]


@pytest.mark.parametrize("text, message", [
    ("final_counter X 800", "f:1: expected NAME AXIS VALUE TOLERANCE"),
    ("top_speed X 1 1", "f:1: unknown feature top_speed X"),
    ("final_pos Q 1 1", "f:1: unknown feature final_pos Q"),
    ("final_pos X one 1", "f:1: VALUE and TOLERANCE must be numbers"),
])
def test_bad_features_files(text, message):
    with pytest.raises(FeatureError, match=message):
        read_expected(text, "f")


def test_update_keeps_tolerances_and_comments():
    new = update_expected(FEATURES, {("final_counter", "X"): 791.0, ("duration", "-"): 2.25})
    assert read_expected(new)[0].value == 791 and read_expected(new)[0].tolerance == 5
    assert "# within Range" in new and new.startswith("# comment line\n")
    assert read_expected(new)[1].value == 2.25
