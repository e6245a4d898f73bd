"""Each regression scenario (tests/regression/scenarios) run and compared with
its golden transcript and expected trace features (harness/analysis/regression.py).
Goldens: `make regression-update` rewrites them and prints what changed."""
import pytest

from harness.analysis import regression
from harness.controllers.scripted import run_five_file
from tests.run.common import needs_build

pytestmark = needs_build


@pytest.mark.parametrize("scenario", regression.scenarios(), ids=lambda s: s.name)
def test_scenario(scenario, tmp_path):
    reason = regression.skip_reason(scenario)
    if reason:
        pytest.skip(reason)
    outcome = regression.run(scenario, tmp_path, five_runner=run_five_file)
    problems = regression.problems(scenario, outcome)
    assert not problems, f"{scenario.name}:\n" + "\n".join(problems)


def test_error_midway_runs_nothing_after_the_failing_line(tmp_path):
    scenario = regression.Scenario(regression.SCENARIOS / "error-midway.script")
    outcome = regression.run(scenario, tmp_path)
    assert outcome.status == 1
    assert outcome.stderr.startswith(f"{scenario.path}:7: Error: undefined word: NO-SUCH-WORD")
    assert "GREET hello ok\nNO-SUCH-WORD" in outcome.transcript
    assert outcome.transcript.count("GREET hello") == 1 and "3 4 *" not in outcome.transcript


def test_a_changed_golden_is_reported_with_a_diff(tmp_path):
    scenario = regression.Scenario(regression.SCENARIOS / "boot.script")
    outcome = regression.run(scenario, tmp_path)
    outcome.transcript = outcome.transcript.replace("7 SQUARE . 49", "7 SQUARE . 50")
    outcome.measured[("end_stop_rows", "Z")] = 3.0
    found = regression.problems(scenario, outcome)
    assert any("-7 SQUARE . 49" in p and "+7 SQUARE . 50" in p for p in found)
    assert "end_stop_rows Z: measured 3.000, expected 0 +- 0" in found
