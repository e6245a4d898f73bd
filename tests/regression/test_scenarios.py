"""Each regression scenario (tests/regression/scenarios) run and compared with
its golden transcript and expected trace features (harness/analysis/regression.py).
Goldens: `make regression-update` rewrites them and prints what changed."""
import dataclasses

import pytest

from harness.analysis import regression
from harness.controllers.scripted import run_five_file
from tests.run.common import needs_build

pytestmark = needs_build


@pytest.fixture(scope="module")
def outcome_of(tmp_path_factory):
    """outcome_of(name) -> the outcome of scenario NAME's run: each scenario runs
    once for the module's tests (the last two read boot's and error-midway's
    again), each in its own directory."""
    outcomes = {}

    def outcome(name):
        if name not in outcomes:
            scenario = regression.Scenario(regression.SCENARIOS / f"{name}.script")
            outcomes[name] = regression.run(scenario, tmp_path_factory.mktemp(name),
                                            five_runner=run_five_file)
        return outcomes[name]
    return outcome


@pytest.mark.parametrize("scenario", regression.scenarios(), ids=lambda s: s.name)
def test_scenario(scenario, outcome_of):
    problems = regression.problems(scenario, outcome_of(scenario.name))
    # asked only of a scenario that fails: the answer costs a run of 1000 LOAD
    if problems and (reason := regression.skip_reason(scenario)):
        pytest.skip(reason)
    assert not problems, f"{scenario.name}:\n" + "\n".join(problems)


def test_error_midway_runs_nothing_after_the_failing_line(outcome_of):
    scenario = regression.Scenario(regression.SCENARIOS / "error-midway.script")
    outcome = outcome_of("error-midway")
    assert outcome.status == 1
    assert outcome.stderr.startswith(f"{scenario.path}:7: Error: undefined word: NO-SUCH-WORD")
    assert "GREET hello ok\nNO-SUCH-WORD" in outcome.transcript
    assert outcome.transcript.count("GREET hello") == 1 and "3 4 *" not in outcome.transcript


def test_a_changed_golden_is_reported_with_a_diff(outcome_of):
    scenario = regression.Scenario(regression.SCENARIOS / "boot.script")
    run = outcome_of("boot")
    outcome = dataclasses.replace(run, transcript=run.transcript.replace(
        "7 SQUARE . 49", "7 SQUARE . 50"), measured=dict(run.measured))
    outcome.measured[("end_stop_rows", "Z")] = 3.0
    found = regression.problems(scenario, outcome)
    assert any("-7 SQUARE . 49" in p and "+7 SQUARE . 50" in p for p in found)
    assert "end_stop_rows Z: measured 3.000, expected 0 +- 0" in found
