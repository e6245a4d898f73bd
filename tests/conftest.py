"""Shared pytest set-up: the repository root is importable (harness package)."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


# make test's order: the longest modules first (tests/schedule.py)
import pytest  # noqa: E402

from tests.schedule import DurationLog, LongestFirstScheduling  # noqa: E402

_durations = DurationLog()


@pytest.hookimpl(tryfirst=True)
def pytest_xdist_make_scheduler(config, log):
    return LongestFirstScheduling(config, log) if config.getvalue("dist") == "loadscope" else None


def pytest_runtest_logreport(report):
    if not hasattr(report, "node"):          # xdist's controller receives each worker's reports
        return
    _durations.add(report)


def pytest_sessionfinish(session):
    if getattr(session.config, "workerinput", None) is None:
        _durations.save()
