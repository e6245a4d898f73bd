"""The continuation's measures and figures: path_metrics on paths whose
answers are known, and the plot command's xy and gripper figures."""
import numpy as np
import pytest

from harness.analysis import path_metrics as pm
from harness.analysis import trace
from harness.cli import main

CORNERS = [(0, 0), (100, 0), (100, 100)]


def samples(points, dt=0.01):
    p = np.array(points, float)
    return pm.PathSamples(np.arange(len(p)) * dt, p[:, 0], p[:, 1])


def test_a_path_on_its_segments_deviates_by_nothing():
    path = [(x, 0) for x in range(0, 101, 5)] + [(100, y) for y in range(5, 101, 5)]
    m = pm.measure(samples(path), CORNERS)
    assert m.segment_max == pytest.approx([0, 0]) and m.via_miss == pytest.approx([0, 0])
    assert m.via_speed[1] == pytest.approx(500.0)            # 5 counts per 0.01 s
    # at the corner the central differences span it: |(5, 5)| / 0.02 s
    assert m.via_speed[0] == pytest.approx(50 ** 0.5 / 0.02)


def test_a_cut_corner_and_an_offset_segment():
    # along y = 3 to (97, 3), across to (97, 100): 3 counts off each segment,
    # the corner missed by 3 sqrt(2)
    path = [(x, 3) for x in range(0, 98)] + [(97, y) for y in range(4, 101)]
    m = pm.measure(samples(path), CORNERS)
    assert m.segment_max == pytest.approx([3.0, 3.0])
    assert m.via_miss[0] == pytest.approx(3 * 2 ** 0.5)
    assert m.via_miss[1] == pytest.approx(3.0)


def test_radial_error_of_a_circle():
    t = np.linspace(0, 2 * np.pi, 50)
    xy = pm.PathSamples(t, 10 + 5 * np.cos(t), 20 + 5 * np.sin(t))
    assert np.abs(pm.radial_error(xy, (10, 20), 5)).max() < 1e-12
    assert pm.radial_error(xy, (10, 20), 4).min() == pytest.approx(1.0)


def test_plot_xy_and_gripper_figures(servo_trace, tmp_path, capsys):
    stem = str(tmp_path / "run")
    assert main(["plot", str(servo_trace), "--figure", "xy", "--via", "0,0",
                 "--via", "1000,0", "--out", stem, "--format", "png"]) == 0
    assert main(["plot", str(servo_trace), "--figure", "gripper", "--out", stem,
                 "--format", "png"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run-gripper.png", "run-xy.png"]


@pytest.mark.parametrize("args, message", [
    (["--figure", "xy"], "needs the start point and at least one via point"),
    (["--figure", "xy", "--via", "0,0", "--via", "9,9", "--window", "500:600"],
     "too few x-y samples"),
])
def test_plot_xy_bad_input_writes_nothing(servo_trace, tmp_path, capsys, args, message):
    assert main(["plot", str(servo_trace), "--out", str(tmp_path / "run"), *args]) == 1
    assert message in capsys.readouterr().err and list(tmp_path.iterdir()) == []


def test_gripper_figure_needs_the_gripper_columns(tmp_path, capsys):
    old = tmp_path / "old.csv"
    old.write_text(",".join(trace.HEADER) + "\n0.1,X,2048,0,0,0,0\n")
    assert main(["plot", str(old), "--figure", "gripper", "--out", str(tmp_path / "g")]) == 1
    assert "no gripper columns" in capsys.readouterr().err


def test_via_must_be_two_numbers(servo_trace, tmp_path, capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["plot", str(servo_trace), "--figure", "xy", "--via", "3,x"])
    assert exit_.value.code == 2 and "expected X,Y in counts" in capsys.readouterr().err
