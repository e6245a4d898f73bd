"""The watched words' history the scope draws (harness/lab/word_history.py)."""
from harness.lab.word_history import WordHistory


def test_only_the_ticks_where_a_word_changed_are_kept():
    h = WordHistory(keep=100)
    for tick in range(5):
        h.add(tick / 60, {"Desire.Pos": [0, 0, 0, 0], "Dir": 1, "Weights": [tick]})
    h.add(5 / 60, {"Desire.Pos": [800, 0, 0, 0], "Dir": 1, "Weights": [5]})
    assert h.take(10) == [[0.0, {"Desire.Pos": [0, 0, 0, 0], "Dir": 1}],
                          [5 / 60, {"Desire.Pos": [800, 0, 0, 0], "Dir": 1}]]
    assert h.take(10) == []                          # each change goes out once


def test_a_fast_run_is_thinned_keeping_the_last_change():
    h = WordHistory(keep=1000)
    for tick in range(101):
        h.add(tick / 60, {"Velocity": [tick, 0, 0, 0]})
    ticks = h.take(10)
    assert len(ticks) <= 12 and ticks[0][0] == 0.0
    assert ticks[-1] == [100 / 60, {"Velocity": [100, 0, 0, 0]}]
