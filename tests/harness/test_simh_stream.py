"""simh.stream: the simulator's output line by line, as simh.run gives it whole."""
import pytest

from harness.machine import simh


def test_stream_gives_the_same_output_as_run():
    script = simh.deposit(0o1000, [0o012700, 0o001234, 0]) + "go 1000\nexamine r0\n"
    with simh.stream(script) as out:
        lines = list(out)
    assert "".join(lines) == simh.run(script)
    assert simh.examined("".join(lines))["R0"] == 0o1234


def test_stream_stops_the_simulator_when_the_reader_gives_up():
    script = "".join(f"examine {a:o}\n" for a in range(0, 0o20000, 2))
    with pytest.raises(KeyError):
        with simh.stream(script) as out:
            next(out)
            raise KeyError("stop reading")


def test_stream_missing_simulator(tmp_path):
    with pytest.raises(simh.SimhError, match="does not exist"):
        with simh.stream("", simulator=tmp_path / "nope"):
            pass
