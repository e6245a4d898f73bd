"""The figures, inspected as matplotlib objects (axes, series, labels), and the
files they are saved to. (harness.analysis.plots comes from a fixture: matplotlib
is imported when these tests run, not when make test's every worker collects
every module.)"""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from harness.analysis import moves as mv
from harness.analysis import trace

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def plots():
    from harness.analysis import plots
    return plots


@pytest.fixture(scope="module")
def tr(servo_trace):
    return trace.read(servo_trace)


def lines_by_label(ax):
    return {line.get_label(): line for line in ax.get_lines()}


def texts(ax):
    return {t.get_text() for t in ax.texts}


def test_moves_figure_long_and_short_side_by_side(plots, tr):
    fig = plots.moves_figure(tr, "X")
    panels = [ax for ax in fig.axes if ax.get_lines()]
    assert len(panels) == 2
    assert "Figure 2" in fig.get_suptitle() and "Axis X" in fig.get_suptitle()
    x = tr.axis("X")
    long_, short = mv.long_and_short(mv.find_moves(x))
    for ax, move, name in zip(panels, (long_, short), ("long move", "short move")):
        assert ax.get_title().startswith(name)
        assert "counts" in ax.get_xlabel() and "counts/s" in ax.get_ylabel()
        assert {"D0", "D1", "D2", "D3"} <= texts(ax)
        assert ax.get_legend() is not None
        series = lines_by_label(ax)
        cmd, act = series["commanded velocity (vcmd)"], series["actual velocity (vel)"]
        rows = slice(move.first - 1, move.rest + 1)
        np.testing.assert_allclose(cmd.get_xdata(), (x.pos[rows] - move.d0) * move.direction)
        np.testing.assert_allclose(cmd.get_ydata(), x.vcmd[rows] * move.direction)
        np.testing.assert_allclose(act.get_ydata(), x.vel[rows] * move.direction)
        # the D marks: vertical lines at D0..D3, measured from D0
        marks = [ln.get_xdata()[0] for ln in ax.get_lines() if ln.get_label().startswith("_")]
        expected = [(d - move.d0) * move.direction for d in (move.d0, move.d1, move.d2, move.d3)]
        np.testing.assert_allclose(marks, expected)


def test_moves_figure_one_panel_per_window(plots, tr):
    x = tr.axis("X")
    _, short = mv.long_and_short(mv.find_moves(x))
    fig = plots.moves_figure(tr, "X", windows=[(short.t0 - 0.01, None)])
    (ax,) = [a for a in fig.axes if a.get_lines()]
    assert ax.get_title().startswith("move starting in")
    with pytest.raises(plots.PlotError, match="no move on axis X starts in 50"):
        plots.moves_figure(tr, "X", windows=[(50, 60)])
    with pytest.raises(plots.PlotError, match="no moves on axis Y"):
        plots.moves_figure(tr, "Y")


def test_time_figure_rows_per_axis(plots, tr):
    fig = plots.time_figure(tr, "XY", windows=[(0.5, 1.5)])
    assert len(fig.axes) == 4
    pos_x, vel_x, pos_y, _ = fig.axes
    assert pos_x.get_title() == "axis X: position" and pos_y.get_title() == "axis Y: position"
    assert pos_x.get_ylabel() == "position, counts" and vel_x.get_ylabel() == "velocity, counts/s"
    assert all(ax.get_xlabel() == "simulated time, s" for ax in fig.axes)
    assert set(lines_by_label(vel_x)) == {"commanded velocity (vcmd)", "actual velocity (vel)"}
    t = lines_by_label(pos_x)["position (pos)"].get_xdata()
    assert t.min() >= 0.5 and t.max() <= 1.5


def test_zero_figure_held_codes_and_offsets(plots, tr):
    fig = plots.zero_figure(tr, "XY", offsets={"X": 3.0})
    ax_x, ax_y = fig.axes
    assert ax_x.get_ylabel() == "DAC code (2048 = 0 V)" and "0-Vel" in fig.get_suptitle()
    series = lines_by_label(ax_x)
    held = series["DAC code while held idle (0-Vel)"]
    t, codes = mv.held_codes(tr.axis("X"))
    np.testing.assert_array_equal(held.get_xdata(), t)
    np.testing.assert_array_equal(held.get_ydata(), codes)
    (given,) = [ln for label, ln in series.items() if label.startswith("2048 + given offset")]
    assert list(given.get_ydata()) == [2051.0, 2051.0]
    assert any(label.startswith("plant's zero from the trace") for label in series)
    # y: one code only, so no Kv, no line from the trace, no offset given
    assert set(lines_by_label(ax_y)) == {"DAC code while held idle (0-Vel)",
                                         "DAC code, every row"}
    np.testing.assert_array_equal(series["DAC code, every row"].get_ydata(), tr.axis("X").dac)


def test_save_writes_valid_png_and_svg(plots, tr, tmp_path):
    fig = plots.time_figure(tr, "X")
    engine = fig.get_layout_engine()
    png, svg = tmp_path / "f.png", tmp_path / "f.svg"
    plots.save(fig, [png, svg])
    assert png.read_bytes()[:8] == PNG_MAGIC
    assert ET.parse(svg).getroot().tag == "{http://www.w3.org/2000/svg}svg"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.png", "f.svg"]
    # laid out once for both formats (plot_files.py), the PNG is still savefig's own
    assert fig.get_layout_engine() is engine
    fig.savefig(tmp_path / "own.png", dpi=100)
    assert (tmp_path / "own.png").read_bytes() == png.read_bytes()


def test_save_failure_leaves_nothing(plots, tr, tmp_path):
    fig = plots.zero_figure(tr, "Y")           # one panel: the cheapest file to leave
    with pytest.raises(ValueError):
        plots.save_all([(fig, [tmp_path / "ok.png", tmp_path / "bad.xyz"])])
    assert list(tmp_path.iterdir()) == []


def test_same_figure_same_svg(plots, tr, tmp_path):
    """Built and saved twice, a figure gives the same bytes (fixed SVG ids, no date)."""
    for name in ("a.svg", "b.svg"):
        plots.save(plots.zero_figure(tr, "Y"), [tmp_path / name])
    assert (tmp_path / "a.svg").read_bytes() == (tmp_path / "b.svg").read_bytes()


def test_moves_figure_says_when_there_is_no_short_move(plots, tmp_path):
    """The 1983 servo starts every move at full speed: both moves reach MaxVel,
    so one panel, and the title says why; z-style drift at DAC 2048 is no move."""
    rows = ["time_s,axis,dac,vcmd,vel,pos,counter"]
    t = 0.0
    for dac, vel, pos in ([(2048, -880, -880 * k / 60) for k in range(30)]      # drift
                          + [(2048, 0, -440)] * 5
                          + [(2348, 5800, -440 + 96 * k) for k in range(40)]    # long
                          + [(2049, 0, 3400)] * 5
                          + [(2349, 5800, 3400 + 96 * k) for k in range(4)]     # shorter
                          + [(2049, 0, 3800)] * 5):
        rows.append(f"{t:.6f},X,{dac},{vel},{vel},{pos},{int(pos)}")
        t += 1 / 60
    path = tmp_path / "full-speed.csv"
    path.write_text("\n".join(rows) + "\n")
    fig = plots.moves_figure(trace.read(path), "X")
    (ax,) = [a for a in fig.axes if a.get_lines()]
    assert ax.get_title().startswith("long move: -440 to ")
    assert "no short move: every move here peaks at the long move's 300 codes" \
        in " ".join(fig.get_suptitle().split())         # the title wraps to the panel
