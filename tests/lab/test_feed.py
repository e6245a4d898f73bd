"""The live streams' parsers (harness/lab/feed.py), on text as the devices write it."""
import random

from harness.lab.feed import Lines, WordRows, lab_row, memory_of, other_lines, plant_lines, \
    plant_rows, thin
from harness.machine.plant_rows import AXES, AXIS, COLUMNS


def test_lines_keep_a_partial_line_for_the_next_read():
    lines = Lines()
    assert lines.feed(b"a,1\nb,") == b"a,1\n"
    assert lines.feed(b"2\n\nc") == b"b,2\n\n"
    assert lines.feed(b"") == b""


def test_p_rows_and_the_others_are_told_apart_in_a_block():
    block = b"W,0.1,6,1\nP,0.1,X,1\nP\nPX,1\n\nR,0.1,7\nP,0.1,Y,2\nI,0.1,100=6\n"
    assert other_lines(block) == [b"W,0.1,6,1", b"P", b"PX,1", b"R,0.1,7", b"I,0.1,100=6"]
    assert plant_lines(block + b"P,0.2,Z,3\n") == [b"P,0.1,X,1", b"P,0.1,Y,2", b"P,0.2,Z,3"]
    assert other_lines(b"") == [] and plant_lines(b"") == []


def test_plant_rows_in_the_trace_columns_and_extra_columns_are_ignored():
    assert plant_rows([b"P,0.016667,Z,2100,1015.560,12.500,-4000.000,-3,1.25,1,7,9"]) == [
        [0.016667, 2, 2100, 1015.56, 12.5, -4000.0, -3, 1.25, 1, 7]]
    assert plant_rows([b"P,0.1,Q,1,2,3,4,5,0,0,0"]) == []      # no such axis
    assert plant_rows([b"P,0.1,X,1,2,3,4,5"]) == []            # no gripper columns


def decoded_one_by_one(line):
    """How the server read a P row before it kept the bytes (one LabRow each, as text)."""
    fields = lab_row(line).fields
    if len(fields) < len(COLUMNS):
        return None
    try:
        return [AXES.index(text) if k == AXIS else float(text)
                for k, text in enumerate(fields[:len(COLUMNS)])]
    except ValueError:
        return None


def test_plant_rows_from_the_bytes_are_the_rows_decoded_one_by_one():
    """Readable rows give the same numbers, bit for bit; unreadable ones are dropped
    as before (wrong column counts, numbers float() does not read, bytes that are
    not ASCII). The one difference: an axis must be one of AXES' letters, where
    AXES.index took any piece of "XYZT" ("", "YZ") for an axis."""
    good = "P,{t},{axis},{dac},{vcmd:.3f},{vel:.3f},{pos:.3f},{counter},{grip},{contact},{missed}"
    rng = random.Random(19)
    lines = [good.format(t=tick / 240, axis=AXES[tick % 4], dac=rng.randrange(4096),
                         vcmd=rng.uniform(-50, 50), vel=rng.uniform(-3, 3),
                         pos=rng.uniform(-9000, 9000), counter=rng.randrange(-9000, 9000),
                         grip=rng.random(), contact=tick % 2, missed=0).encode()
             for tick in range(400)]
    lines += [b"P,0.1,X,1,2,3,4,5,0,0,0,extra,more", b"P,1e3,T,inf,-0,nan, 7 ,1_0,0,0,0",
              b"P,0.1,X,1,2,3,4,5,0,0", b"P", b"P,", b"P,0.1,X,1,2,x,4,5,0,0,0",
              b"P,0.1,X,1,2,3,4,5,0,0,0\xff", b"P,0.1,\xff,1,2,3,4,5,0,0,0",
              b"P,0.1,x,1,2,3,4,5,0,0,0", b"P,,X,1,2,3,4,5,0,0,0", b"P,0.1,X,0x1,2,3,4,5,0,0,0"]
    rng.shuffle(lines)
    before = [numbers for numbers in map(decoded_one_by_one, lines) if numbers]
    assert repr(plant_rows(lines)) == repr(before)
    assert len(before) == 402
    assert decoded_one_by_one(b"P,0.1,YZ,1,2,3,4,5,0,0,0") is not None      # the difference
    assert plant_rows([b"P,0.1,YZ,1,2,3,4,5,0,0,0", b"P,0.1,,1,2,3,4,5,0,0,0"]) == []


def test_lab_rows():
    assert lab_row(b"W,0.050000,3,1,65535").kind == "W"
    m = lab_row(b"M,1000,5,6")
    assert memory_of(m) == (0o1000, [5, 6])
    assert lab_row(b"S,1.0,pause,0").fields == ["1.0", "pause", "0"]
    assert lab_row(b"") is None


def test_thin_keeps_every_axis_share():
    rows = [[i / 100, i % 4, 0, 0, 0, 0, 0] for i in range(400)]
    kept = thin(rows, 100)
    assert len(kept) == 100
    assert [sum(1 for r in kept if r[1] == a) for a in range(4)] == [25] * 4
    assert thin(rows[:10], 100) == rows[:10]


def test_word_rows_decode_a_w_row_again_only_when_its_words_change():
    rows = WordRows()
    first = rows.read(b"W,0.050000,3,1,65535")
    assert first == (0.05, 3, [1, 65535])
    again = rows.read(b"W,0.066667,4,1,65535")
    assert again[:2] == (0.066667, 4) and again[2] is first[2]
    assert rows.read(b"W,0.083333,5,2,65535")[2] == [2, 65535]
    assert rows.read(b"W,0.1,6") == (0.1, 6, [])
