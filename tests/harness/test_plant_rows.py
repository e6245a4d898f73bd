"""The plant's row and SHOW PLANT read in one place (harness/machine/plant_rows.py),
held against what build/pdp11 says of itself (SHOW PLANT LAYOUT, the trace's header)."""
import pytest

from harness.machine import plant_rows, simh
from harness.machine.plant_rows import AXES, COLUMNS, parse_layout


def test_the_simulator_agrees_with_the_python_home(tmp_path):
    layout = plant_rows.layout()
    assert layout.columns == COLUMNS and "".join(sorted(layout.units)) == "".join(sorted(AXES))
    assert layout.units == {"X": "in", "Y": "in", "Z": "in", "T": "deg"}
    assert layout.per_unit["X"] == 800 and layout.per_unit["T"] == pytest.approx(16000 / 360)
    assert layout.stops["Z"] == (-4000, 2400)
    trace = tmp_path / "t.csv"
    simh.run(f"attach plant {trace}\ndetach plant\n")
    assert trace.read_text().splitlines()[0] == ",".join(COLUMNS)


def test_the_layout_follows_a_set_and_is_what_the_page_learns():
    changed = parse_layout(simh.run("set plant x pmin=-100\nshow plant layout\n"))
    assert changed.stops["X"] == (-100, 9600)
    message = changed.message()
    assert message["axes"] == AXES and message["columns"] == list(COLUMNS)
    assert len(message["units"]) == len(message["per_unit"]) == len(AXES)


def test_a_layout_of_other_columns_is_refused():
    text = "columns time_s,axis,dac\n" + "".join(f"axis {a} in 800 -1 1\n" for a in AXES)
    with pytest.raises(ValueError, match="not understood"):
        parse_layout(text)
    assert "columns" not in simh.run("show plant\n")          # only when named


def test_show_plant_fits_80_columns_and_still_parses():
    """An 80-column terminal (the lab page's, make run's) shows SHOW PLANT unwrapped,
    the gripper's lines with a part placed included (issue 18)."""
    out = simh.run("set plant gripper object=1,partx=800,party=800,partz=400\n"
                   "set plant x pos=-9000\nshow plant\n")
    lines = out[out.index("PLANT, "):].splitlines()[1:]
    assert len(lines) >= 12 and max(len(ln) for ln in lines) < 80, lines
    assert plant_rows.parse_show_plant(out)["X"]["pos"] == -9000
    assert plant_rows.parse_show_gripper(out)["part"] == (800, 800, 400)
