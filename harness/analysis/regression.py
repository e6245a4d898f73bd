"""The regression scenarios of tests/regression/scenarios: run, compare, update.

A scenario is NAME.script (a console script, docs/console.md) with beside it
  NAME.expected   the golden transcript, compared exactly except that the
                  banner's "N bytes free" is masked (it changes with the kernel)
  NAME.features   expected plant-trace features with tolerances
                  (harness/analysis/trace_features.py)
and, in the script's comments, "# needs: 1000 LOAD" (skipped while the appendix
blocks cannot load on this kernel), "# fails-at: N" (the run must stop with
exit status 1 at script line N, naming it, and run nothing after it) and
"# machines: five" (the script is the 11/23's in a run of the five machines of
issue 21, harness/controllers: NAME.expected holds the five transcripts, each
under a "===== member" line; the runner comes from the caller, `five_runner`,
as this package may not import that one).
"""
import difflib
import functools
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

from harness.analysis import trace_features
from harness.analysis.trace import read as read_trace
from harness.machine.build import ROOT
from harness.machine.script_run import ERRORS, run_file

SCENARIOS = ROOT / "tests" / "regression" / "scenarios"
FREE = re.compile(r"\d+ bytes free")
META = re.compile(r"^#\s*(needs|fails-at|options|machines):\s*(.*?)\s*$", re.M)


@dataclass
class Scenario:
    path: Path

    @property
    def name(self):
        return self.path.stem

    def meta(self, key):
        return [v for k, v in META.findall(self.path.read_text()) if k == key]

    @property
    def needs_load(self):
        return "1000 LOAD" in self.meta("needs")

    @property
    def fails_at(self):
        found = self.meta("fails-at")
        return int(found[0]) if found else None

    @property
    def five(self):
        return "five" in self.meta("machines")

    @property
    def options(self):
        return " ".join(self.meta("options")).split()

    def sibling(self, suffix):
        return self.path.with_suffix(suffix)


@dataclass
class Outcome:
    status: int
    stderr: str
    transcript: str
    measured: dict


def scenarios(names=()):
    if names:
        missing = [n for n in names if not (SCENARIOS / f"{n}.script").is_file()]
        if missing:
            raise ValueError(f"no scenario {', '.join(missing)} in {SCENARIOS}")
        return [Scenario(SCENARIOS / f"{n}.script") for n in names]
    return [Scenario(p) for p in sorted(SCENARIOS.glob("*.script"))]


def run_options(options):
    """The keyword arguments of script_run.run_file for a scenario's `# options:`
    (the `run` command's --keep-going and --line-limit SECONDS)."""
    kwargs, words = {}, list(options)
    while words:
        word = words.pop(0)
        if word == "--keep-going":
            kwargs["keep_going"] = True
        elif word == "--line-limit" and words:
            kwargs["line_limit"] = float(words.pop(0))
        else:
            raise ValueError(f"scenario option {word!r}: only --keep-going and "
                             "--line-limit SECONDS are known")
    return kwargs


def run(scenario, out_dir, five_runner=None):
    """Run the scenario (script_run.run_file, as the `run` command does, with the
    scenario's options; a five-machine one with `five_runner`, which takes the
    same arguments) into out_dir; its outcome, stderr as `run` prints it."""
    transcript = Path(out_dir) / f"{scenario.name}.transcript"
    trace = Path(out_dir) / f"{scenario.name}.trace.csv"
    runner = run_file
    if scenario.five:
        if five_runner is None:
            raise ValueError(f"{scenario.name}: a five-machine scenario needs the caller's "
                             "runner (python -m harness regress has it)")
        runner = five_runner
    try:
        _, result = runner(scenario.path, transcript, trace, **run_options(scenario.options))
    except ERRORS as err:
        return Outcome(1, "".join(f"python -m harness run: error: {line}\n"
                                  for line in str(err).splitlines()), "", {})
    stderr = "".join(f"{f.where(str(scenario.path))}\n" for f in result.failures)
    return Outcome(1 if result.failures else 0, stderr, transcript.read_text(),
                   trace_features.features(read_trace(trace)))


def masked(transcript):
    return FREE.sub("N bytes free", transcript)


def problems(scenario, outcome):
    """Everything in which the outcome differs from the goldens."""
    found = []
    expected_status = 1 if scenario.fails_at else 0
    if outcome.status != expected_status:
        found.append(f"exit status {outcome.status}, expected {expected_status}: "
                     f"{outcome.stderr.strip()}")
    if scenario.fails_at:
        where = f"{scenario.path}:{scenario.fails_at}: "
        if not outcome.stderr.startswith(where):
            found.append(f"the failure should be reported as {where}...; got "
                         f"{outcome.stderr.strip()!r}")
    golden = scenario.sibling(".expected")
    if not golden.exists():
        found.append(f"no golden transcript {golden.name}: run make regression-update")
    elif masked(golden.read_text()) != masked(outcome.transcript):
        found.append("transcript differs from the golden:\n" + diff(golden.read_text(),
                                                                     outcome.transcript))
    features = scenario.sibling(".features")
    if features.exists():
        expected = trace_features.read_expected(features.read_text(), str(features))
        found += trace_features.check(outcome.measured, expected)
    return found


def diff(old, new, name="transcript"):
    return "".join(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                        f"golden {name}", f"this run's {name}"))


def update(scenario, outcome):
    """Rewrite the goldens from this outcome; the report of what changed."""
    report = []
    golden = scenario.sibling(".expected")
    old = golden.read_text() if golden.exists() else ""
    if old != outcome.transcript:
        report.append(diff(old, outcome.transcript) or f"{golden.name}: written")
        golden.write_text(outcome.transcript)
    features = scenario.sibling(".features")
    if features.exists():
        old_text = features.read_text()
        new_text = trace_features.update_expected(old_text, outcome.measured)
        if new_text != old_text:
            report.append(diff(old_text, new_text, features.name))
            features.write_text(new_text)
    return report


@functools.lru_cache(maxsize=None)
def appendix_loads():
    """(True, "") if 1000 LOAD loads on this kernel, else (False, its error)."""
    probe = Scenario(Path("probe.script"))
    with tempfile.TemporaryDirectory() as tmp:
        probe.path = Path(tmp) / "probe.script"
        probe.path.write_text("1000 LOAD\n")
        outcome = run(probe, tmp)
    if outcome.status == 0:
        return True, ""
    return False, outcome.stderr.strip().split(": ", 1)[-1]


def skip_reason(scenario):
    if scenario.needs_load:
        loads, error = appendix_loads()
        if not loads:
            return ("needs the resident assembler: 1000 LOAD does not load on this "
                    f"kernel yet ({error})")
    return ""


def main(names=(), update_goldens=False, five_runner=None):
    """Run scenarios, print a report; the exit status (0: all agree)."""
    bad = 0
    for scenario in scenarios(names):
        reason = skip_reason(scenario)
        if reason:
            print(f"{scenario.name}: skipped: {reason}")
            continue
        with tempfile.TemporaryDirectory() as tmp:
            outcome = run(scenario, tmp, five_runner)
        if update_goldens:
            status = [p for p in problems(scenario, outcome) if p.startswith(("exit", "the f"))]
            for p in status:
                print(f"{scenario.name}: WARNING: {p}")
            changes = update(scenario, outcome)
            print(f"{scenario.name}: " + ("updated\n" + "\n".join(changes)
                                          if changes else "unchanged"))
            continue
        found = problems(scenario, outcome)
        bad += bool(found)
        print(f"{scenario.name}: " + ("FAILED\n  " + "\n  ".join(found) if found else "ok"))
    return 1 if bad else 0
