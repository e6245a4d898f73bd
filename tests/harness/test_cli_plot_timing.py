"""The plot and timing subcommands from the command line: files written, and bad
input: a clear message, a non-zero exit, nothing written."""
import re
import subprocess
import sys

import pytest

from harness.cli import main
from harness.machine.build import ROOT
from timing_programs import counting_handler

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def run_cli(*argv):
    """Exit status, stdout and stderr of `python -m harness ARGV`."""
    proc = subprocess.run([sys.executable, "-m", "harness", *map(str, argv)], cwd=ROOT,
                          capture_output=True, text=True)
    return proc.returncode, proc.stdout, proc.stderr


def test_plot_writes_every_figure(servo_trace, tmp_path, cli):
    stem = tmp_path / "run"
    status, out, err = cli("plot", servo_trace, "--out", stem, "--axis", "XY", "--offset", "X=3")
    assert status == 0, err
    names = sorted(p.rsplit("/", 1)[1] for p in out.split())
    # moves: x only (y has none); time and zero: x and y
    assert names == sorted(f"run-{f}.{e}" for f in ("moves-X", "time", "zero")
                           for e in ("png", "svg"))
    for path in map(lambda p: tmp_path / p, names):
        head = path.read_bytes()[:200]
        assert head.startswith(PNG_MAGIC) if path.suffix == ".png" else b"<svg" in head
    assert sorted(p.name for p in tmp_path.iterdir()) == names      # no temporary left


def test_plot_default_names_beside_the_trace(servo_trace, tmp_path, capsys):
    trace = tmp_path / "copy.csv"
    trace.write_bytes(servo_trace.read_bytes())
    # one panel: the names are what is checked here, the figure's rows are test_plots.py's
    assert main(["plot", str(trace), "--figure", "zero", "--format", "png", "--axis", "Y"]) == 0
    assert capsys.readouterr().out.split() == [str(tmp_path / "copy-zero.png")]


@pytest.mark.parametrize("args, message", [
    (["missing.csv"], "missing.csv: no such file"),
    (["notatrace.csv"], "not a plant trace"),
    (["TRACE", "--figure", "moves", "--axis", "Y"], "no moves on axis Y"),
    (["TRACE", "--figure", "moves", "--window", "50:60"], "no moves to draw on any axis"),
    (["TRACE", "--out", "nodir/run"], "no such directory"),
])
def test_plot_bad_input_writes_nothing(servo_trace, tmp_path, capsys, args, message):
    (tmp_path / "notatrace.csv").write_text("this is not a trace\n")
    before = sorted(tmp_path.iterdir())
    argv = [str(servo_trace) if a == "TRACE" else str(tmp_path / a) if a.endswith(".csv")
            or a.startswith("nodir") else a for a in args]
    assert main(["plot", "--out", str(tmp_path / "run"), *argv[:1], *argv[1:]]
                if "--out" not in args else ["plot", *argv]) == 1
    err = capsys.readouterr().err
    assert err.startswith("python -m harness plot: error: ") and message in err
    assert sorted(tmp_path.iterdir()) == before


@pytest.mark.parametrize("option, message", [
    (["--window", "2:1"], "START is after END"),
    (["--window", "soon"], "expected START:END"),
    (["--axis", "Q"], "axes are letters from XYZT"),
    (["--offset", "X3"], "expected AXIS=CODES"),
    (["--kv", "0"], "expected a positive number"),
    (["--figure", "pie"], "invalid choice"),
])
def test_plot_bad_options_are_usage_errors(servo_trace, tmp_path, capsys, option, message):
    with pytest.raises(SystemExit) as exit_:
        main(["plot", str(servo_trace), "--out", str(tmp_path / "run"), *option])
    out, err = capsys.readouterr()
    assert exit_.value.code == 2 and message in err and out == ""
    assert list(tmp_path.iterdir()) == []


def test_timing_cli(tmp_path):
    """The command line's own start: a real `python -m harness` (the other tests
    call it in this process)."""
    setup = tmp_path / "setup.ini"
    setup.write_text(counting_handler().script(start=False))
    status, out, err = run_cli("timing", setup, "--vector", "100",
                               "--instructions", "20000", "--name", "counter")
    assert status == 0, err
    assert out.startswith("counter, from 001400 through its RTI:")
    assert "per 60 Hz tick: 27.300 us" in out


@pytest.mark.parametrize("args, status, message", [
    (["missing.ini", "--entry", "1400"], 1, "missing.ini: no such setup file"),
    (["SETUP", "--entry", "1401"], 2, "expected an even address"),
    (["SETUP", "--entry", "9"], 2, "expected an octal address"),
    (["SETUP"], 2, "give SETUP and one of --entry, --vector (or --servo)"),
    (["SETUP", "--entry", "1000", "--instructions", "0"], 2, "expected a whole number"),
    (["SETUP", "--entry", "2000", "--instructions", "1000"], 1, "never ran through its RTI"),
])
def test_timing_bad_input(tmp_path, capsys, args, status, message):
    setup = tmp_path / "setup.ini"
    setup.write_text(counting_handler().script(start=False))
    argv = [str(setup) if a == "SETUP" else str(tmp_path / a) if a.endswith(".ini") else a
            for a in args]
    try:
        got = main(["timing", *argv])
    except SystemExit as exit_:
        got = exit_.code
    out, err = capsys.readouterr()
    assert got == status and message in err and out == ""


def test_plot_a_trace_of_dac_writes_only(tmp_path, capsys):
    """SET PLANT SAMPLE=0: rows only at DAC writes, here x's alone."""
    from harness.machine import simh
    from servo_program import servo_program, trace_script
    path = tmp_path / "writes.csv"
    simh.run(trace_script(servo_program(), path, extra="set plant sample=0\n"))
    assert main(["plot", str(path), "--figure", "time", "--format", "png"]) == 0
    assert capsys.readouterr().out.split() == [str(tmp_path / "writes-time.png")]
    assert main(["plot", str(path), "--axis", "Y"]) == 1
    assert "no rows for axis Y (the trace has X)" in capsys.readouterr().err


def test_timing_servo_in_one_command(capsys):
    """The servo during a move, as make bench-robot prices it: 0.6 s = 36 ticks.
    docs/servo.md's cost table is what it measures (instruction counts and KDF11-A
    prices, no host time): a kernel change that moves it shows here."""
    assert main(["timing", "--servo", "move"]) == 0
    out = capsys.readouterr().out
    assert "Interrupt.Servo, during a move" in out
    got = re.search(r": (\d+) ticks, ([\d.]+) instructions and (\d+) us per tick", out)
    row = re.search(r"^\| during a move [^|]*\| (\d+) \| ([\d.]+) \| (\d+) \|",
                    (ROOT / "docs" / "servo.md").read_text(), re.M)
    assert got[1] == row[1] == "36"
    for measured, documented in zip(map(float, got.groups()[1:]), map(float, row.groups()[1:])):
        assert abs(measured - documented) <= 0.03 * documented, (measured, documented)


def test_timing_servo_takes_no_setup(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["timing", "--servo", "idle", "setup.ini"])
    assert stop.value.code == 2
    assert "--servo prepares its own run" in capsys.readouterr().err
