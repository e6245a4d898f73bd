"""Reading plant traces: a real one from build/pdp11, and files that are not traces."""
import numpy as np
import pytest

from harness.analysis import trace
from harness.analysis.trace import HEADER, TraceError

GOOD_ROW = "0.016666667,X,2148,1894.410,1070.820,10.144,10"


def test_real_trace_reads_whole(servo_trace):
    tr = trace.read(servo_trace)
    lines = servo_trace.read_text().splitlines()
    assert lines[0] == ",".join(HEADER + trace.GRIPPER_COLUMNS)
    assert tr.gripper is not None and tr.gripper.opening[0] == 2.0   # power-up: open
    assert tr.axes == "XYZT"
    assert sum(len(s) for s in tr.series.values()) == len(lines) - 1
    x = tr.axis("x")
    assert np.all(np.diff(x.time) >= 0)
    # x gets a row at every DAC write (60 a second) besides the samples (60 a second)
    assert len(x) > 1.5 * len(tr.axis("Y"))
    assert x.dac.dtype.kind == "i" and x.counter.dtype.kind == "i"
    first = lines[1].split(",")
    s = tr.axis(first[1])
    assert (s.time[0], s.dac[0], s.pos[0]) == (float(first[0]), int(first[2]), float(first[5]))


def test_window_keeps_rows_in_span(servo_trace):
    x = trace.read(servo_trace).axis("X")
    w = x.window(0.5, 1.0)
    assert len(w) > 0 and w.time.min() >= 0.5 and w.time.max() <= 1.0
    assert len(x.window()) == len(x)


def test_trace_without_gripper_columns_reads(tmp_path):
    path = tmp_path / "old.csv"
    path.write_text(",".join(HEADER) + "\n" + GOOD_ROW + "\n")
    tr = trace.read(path)
    assert tr.gripper is None and tr.axis("X").counter[0] == 10


def test_absent_axis_is_named():
    tr = trace.from_rows([(0.0, "X", 2048, 0.0, 0.0, 0.0, 0)], "t.csv")
    with pytest.raises(TraceError, match="no rows for axis Y .*has X"):
        tr.axis("Y")


@pytest.mark.parametrize("text, message", [
    ("", "empty file"),
    (",".join(HEADER) + "\n", "header only"),
    ("time,axis,dac\n" + GOOD_ROW + "\n", "not a plant trace: the first line is"),
    ("hello world\n", "not a plant trace"),
    (",".join(HEADER) + "\n0.1,X,2048,0,0,0\n", "line 2: 6 fields, expected 7"),
    (",".join(HEADER) + "\n" + GOOD_ROW + "\n0.2,Q,2048,0,0,0,0\n", "line 3: axis is 'Q'"),
    (",".join(HEADER) + "\n0.1,X,5000,0,0,0,0\n", "line 2: dac is '5000'"),
    (",".join(HEADER) + "\n0.1,X,2048,fast,0,0,0\n", "line 2: vcmd is 'fast'"),
    (",".join(HEADER) + "\n0.1,X,2048,0,nan,0,0\n", "line 2: vel is 'nan'"),
    (",".join(HEADER) + "\n0.1,X,2048,0,0,0,40000\n", "line 2: counter is '40000'"),
    (",".join(HEADER) + "\n0.2,X,2048,0,0,0,0\n0.1,X,2048,0,0,0,0\n", "line 3: time 0.1 goes back"),
    (",".join(HEADER) + "\n-1,X,2048,0,0,0,0\n", "line 2: time_s is '-1'"),
    (",".join(HEADER + trace.GRIPPER_COLUMNS) + "\n" + GOOD_ROW + "\n", "7 fields, expected 10"),
    (",".join(HEADER + trace.GRIPPER_COLUMNS) + "\n" + GOOD_ROW + ",2.5,0,0\n",
     "line 2: grip is '2.5'"),
])
def test_bad_traces_say_what_and_where(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(TraceError, match=message) as err:
        trace.read(path)
    assert str(path) in str(err.value)


def test_binary_file_and_missing_and_directory(tmp_path):
    png = tmp_path / "image.csv"
    png.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\xff\xfe")
    with pytest.raises(TraceError, match="not a plant trace"):
        trace.read(png)
    with pytest.raises(TraceError, match="no such file"):
        trace.read(tmp_path / "missing.csv")
    with pytest.raises(TraceError, match="a directory"):
        trace.read(tmp_path)
