"""The order in which make test's workers take the test modules (pytest-xdist,
--dist loadscope): the longest first, so that no long module starts last and
keeps one worker busy after the others are done.

xdist orders the modules by their number of tests; many of ours are few tests
that wait on a simulator for seconds. Each run's wall seconds per module are kept
in build/test-durations.json (written by the controller at the end of a run) and
order the next run; a module not in it (a new one, or a fresh checkout) counts
DEFAULT_TEST_S per test, as xdist's own order would. Only the order changes:
every module still runs whole on one worker, its module fixtures once.

The modules of a SHARED_START group go to one worker together, one after the
other: each worker that draws a figure pays matplotlib's import and its first
figure (the fonts), about a second of CPU, and three workers would pay it three
times; a session fixture two modules read (the ASN's trials, some 2 CPU-s) runs
once on one worker, twice on two."""
import json
from collections import Counter, defaultdict

from xdist.scheduler import LoadScopeScheduling

from harness.machine.build import BUILD

DURATIONS = BUILD / "test-durations.json"
DEFAULT_TEST_S = 0.1
SHARED_START = {"matplotlib": ("tests/harness/test_cli_plot_timing.py",
                               "tests/harness/test_path_plots.py",
                               "tests/harness/test_plots.py"),
                "asn": ("tests/learning/test_asn_robot.py",          # conftest's `learned`
                        "tests/learning/test_asn_script.py")}
GROUP_OF = {module: group for group, modules in SHARED_START.items() for module in modules}


def module_of(nodeid):
    return nodeid.split("::", 1)[0]


def known_durations(path=DURATIONS):
    """module -> wall seconds of its last run ({} when there is none, or it is unreadable)."""
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    return {k: float(v) for k, v in data.items() if isinstance(v, (int, float))} \
        if isinstance(data, dict) else {}


def scope_of(nodeid):
    """The scope a test goes to a worker with: its module's group, else xdist's
    (its module, or its class)."""
    return GROUP_OF.get(module_of(nodeid), nodeid.rsplit("::", 1)[0])


def longest_first(scopes, durations):
    """The scopes (name -> its tests), longest expected first (the sum of their
    modules'); ties keep xdist's order (more tests first)."""
    def expected(item):
        _, tests = item
        return sum(durations.get(module, DEFAULT_TEST_S * n)
                   for module, n in Counter(map(module_of, tests)).items())
    by_count = sorted(scopes.items(), key=lambda item: -len(item[1]))
    return dict(sorted(by_count, key=lambda item: -expected(item)))


class LongestFirstScheduling(LoadScopeScheduling):
    """xdist's loadscope with the work queue in longest_first order."""

    def __init__(self, config, log=None):
        super().__init__(config, log)
        self.durations = known_durations()
        self.ordered = False

    def _split_scope(self, nodeid):
        return scope_of(nodeid)

    def _assign_work_unit(self, node):
        # xdist fills its whole work queue, in its order, before the first assignment
        if not self.ordered and self.workqueue:
            queue = longest_first(dict(self.workqueue), self.durations)
            self.workqueue.clear()
            self.workqueue.update(queue)
            self.ordered = True
        super()._assign_work_unit(node)


class DurationLog:
    """Controller side: each module's wall seconds (setup, call, teardown of its
    tests), written to build/test-durations.json at the end of the run."""

    def __init__(self):
        self.seconds = defaultdict(float)

    def add(self, report):
        self.seconds[module_of(report.nodeid)] += report.duration

    def save(self, path=DURATIONS):
        if not self.seconds or not path.parent.is_dir():
            return
        merged = {**known_durations(path), **{k: round(v, 3) for k, v in self.seconds.items()}}
        tmp = path.with_suffix(".tmp")
        tmp.write_text(json.dumps(dict(sorted(merged.items())), indent=0) + "\n")
        tmp.replace(path)
