"""The live streams' parsers (harness/lab/feed.py), on text as the devices write it."""
from harness.lab.feed import Lines, lab_row, plant_row, thin, words_of


def test_lines_keep_a_partial_line_for_the_next_read():
    lines = Lines()
    assert lines.feed(b"a,1\nb,") == [b"a,1"]
    assert lines.feed(b"2\n") == [b"b,2"]
    assert lines.feed(b"") == []


def test_plant_rows_in_the_trace_columns_and_extra_columns_are_ignored():
    assert plant_row(lab_row(b"P,0.016667,Z,2100,1015.560,12.500,-4000.000,-3,1.25,1,7,9")) == [
        0.016667, 2, 2100, 1015.56, 12.5, -4000.0, -3, 1.25, 1, 7]
    assert plant_row(lab_row(b"P,0.1,Q,1,2,3,4,5,0,0,0")) is None      # no such axis
    assert plant_row(lab_row(b"P,0.1,X,1,2,3,4,5")) is None            # no gripper columns


def test_lab_rows():
    w = lab_row(b"W,0.050000,3,1,65535")
    assert w.kind == "W" and words_of(w) == (0.05, 3, [1, 65535])
    m = lab_row(b"M,1000,5,6")
    assert words_of(m) == (0o1000, [5, 6])
    assert lab_row(b"S,1.0,pause,0").fields == ["1.0", "pause", "0"]
    assert lab_row(b"") is None


def test_thin_keeps_every_axis_share():
    rows = [[i / 100, i % 4, 0, 0, 0, 0, 0] for i in range(400)]
    kept = thin(rows, 100)
    assert len(kept) == 100
    assert [sum(1 for r in kept if r[1] == a) for a in range(4)] == [25] * 4
    assert thin(rows[:10], 100) == rows[:10]
