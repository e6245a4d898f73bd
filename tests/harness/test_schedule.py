"""make test's order (tests/schedule.py): the longest modules first, by the last
run's wall seconds; modules it has not seen by their number of tests; the
modules that draw figures on one worker."""
from types import SimpleNamespace

from tests.schedule import (DEFAULT_TEST_S, SHARED_START, DurationLog, known_durations,
                            longest_first, scope_of)


def scopes(**counts):
    return {f"tests/{name}.py": {f"tests/{name}.py::t{i}": False for i in range(n)}
            for name, n in counts.items()}


def test_known_modules_go_longest_first_and_new_ones_by_their_count():
    queue = scopes(many=30, slow=2, quick=5, new=20)
    durations = {"tests/slow.py": 9.0, "tests/quick.py": 0.2, "tests/many.py": 1.5}
    order = list(longest_first(queue, durations))
    # new: 20 tests at DEFAULT_TEST_S each, between slow (9 s) and many (1.5 s)
    assert 1.5 < 20 * DEFAULT_TEST_S < 9.0
    assert order == ["tests/slow.py", "tests/new.py", "tests/many.py", "tests/quick.py"]
    assert longest_first(queue, durations)["tests/slow.py"] == queue["tests/slow.py"]


def test_without_durations_the_order_is_xdists_most_tests_first():
    queue = scopes(a=3, b=7, c=5)
    assert list(longest_first(queue, {})) == ["tests/b.py", "tests/c.py", "tests/a.py"]


def test_the_modules_that_draw_go_together_and_count_together():
    drawing = SHARED_START["matplotlib"]
    assert {scope_of(f"{m}::t") for m in drawing} == {"matplotlib"}
    assert scope_of("tests/harness/test_trace.py::t[x]") == "tests/harness/test_trace.py"
    queue = {"matplotlib": {f"{m}::t{i}": False for m in drawing for i in range(2)},
             **scopes(slow=1)}
    durations = {drawing[0]: 2.0, drawing[1]: 1.5, "tests/slow.py": 3.0}
    # 2 + 1.5 + (the third, unknown) 2 * DEFAULT_TEST_S > 3
    assert list(longest_first(queue, durations)) == ["matplotlib", "tests/slow.py"]


def test_the_log_sums_each_modules_phases_and_keeps_modules_this_run_skipped(tmp_path):
    path = tmp_path / "durations.json"
    path.write_text('{"tests/other.py": 4.0, "tests/a.py": 99}')
    log = DurationLog()
    for nodeid, seconds in (("tests/a.py::t1", 0.5), ("tests/a.py::t1", 0.25),
                            ("tests/b.py::t[x]", 1.0)):
        log.add(SimpleNamespace(nodeid=nodeid, duration=seconds))
    log.save(path)
    assert known_durations(path) == {"tests/a.py": 0.75, "tests/b.py": 1.0, "tests/other.py": 4.0}


def test_an_unreadable_file_means_no_durations(tmp_path):
    path = tmp_path / "durations.json"
    assert known_durations(path) == {}
    path.write_text("not json")
    assert known_durations(path) == {}
    path.write_text("[1, 2]")
    assert known_durations(path) == {}
