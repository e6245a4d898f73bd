"""`python -m harness run`: determinism, outputs, the disk left alone, bad input."""
import hashlib
import subprocess
import sys

import pytest

from harness.machine.script import MAX_LINE
from harness.machine.kernel_layout import read_kernel_map
from tests.cli_in_process import harness_here as harness
from tests.run.common import PRISTINE, ROOT, needs_build

pytestmark = needs_build

SCRIPT = """# a short session with both directives
1 2 + .
#wait 0.5
#simh show plant
: SQ ( n -- n*n ) DUP * ;
9 SQ .
"""


def harness_process(*args):
    """The real `python -m harness ARGV`, for the test of the start itself."""
    return subprocess.run([sys.executable, "-m", "harness", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)


def test_two_runs_give_identical_files_and_leave_the_disk_alone(tmp_path):
    script = tmp_path / "s.script"
    script.write_text(SCRIPT)
    before = hashlib.sha256(PRISTINE.read_bytes()).hexdigest()
    outputs = []
    # the real start once; the second run in this process (tests/cli_in_process.py)
    for out, start in (("a", harness_process), ("b", harness)):
        (tmp_path / out).mkdir()
        r = start("run", script, "--out", tmp_path / out)
        assert r.returncode == 0, r.stderr
        outputs.append([(tmp_path / out / name).read_bytes()
                        for name in ("s.transcript", "s.trace.csv")])
    assert outputs[0] == outputs[1]
    transcript = outputs[0][0].decode()
    assert "1 2 + . 3  ok\n" in transcript and "9 SQ . 81  ok\n" in transcript
    assert "sim> show plant\nPLANT, seed=1983" in transcript
    assert str(tmp_path) not in transcript and "\r" not in transcript
    assert outputs[0][1].startswith(b"time_s,axis,dac,vcmd,vel,pos,counter,grip,contact,missed\n")
    assert hashlib.sha256(PRISTINE.read_bytes()).hexdigest() == before


def test_default_outputs_beside_the_script_and_named_options(tmp_path):
    script = tmp_path / "s.script"
    script.write_text("1 .\n")
    assert harness("run", script).returncode == 0
    assert (tmp_path / "s.transcript").is_file() and (tmp_path / "s.trace.csv").is_file()
    r = harness("run", script, "--transcript", tmp_path / "t.txt", "--trace", tmp_path / "t.csv")
    assert r.returncode == 0 and (tmp_path / "t.txt").read_text().endswith("1 . 1  ok\n")


def test_a_simulator_named_relative_to_where_the_command_started(tmp_path, monkeypatch):
    """--simulator (make's profile-guided training run names one) is found from the
    directory the command started in, not from the run's own, where it starts."""
    script = tmp_path / "s.script"
    script.write_text("1 .\n")
    monkeypatch.chdir(ROOT / "build")
    r = harness("run", script, "--simulator", "pdp11")
    assert r.returncode == 0, r.stderr


def test_a_line_that_never_finishes_is_stopped_in_simulated_time(tmp_path):
    script = tmp_path / "loop.script"
    script.write_text(": SPIN ( -- ) BEGIN AGAIN ;\nSPIN\n1 .\n")
    r = harness("run", script, "--line-limit", "0.5")
    assert r.returncode == 1
    assert f"{script}:2: the simulator stopped: no prompt within 0.5 simulated seconds" in r.stderr


def test_bye_ends_the_session(tmp_path):
    """The FORTH's BYE (FLUSH, then its HALT) ends a scripted run as it ends the
    console: a clean end when it is the last line, a failure naming what was left."""
    script = tmp_path / "s.script"
    script.write_text("1 .\n: DONE 2 . BYE ; DONE\n")
    r = harness("run", script)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "s.transcript").read_text().endswith(": DONE 2 . BYE ; DONE 2 ")
    script.write_text("1 .\nBYE\n3 .\n")
    r = harness("run", script)
    assert r.returncode == 1
    assert f"{script}:2: BYE ended the session; 1 later steps not run" in r.stderr


RUNAWAY = ': LOOPY ( -- ) CR ." Error: made up" CR BEGIN AGAIN ;\nLOOPY\n2 3 + .\n'
LIMIT_HIT = ("{script}:2: the simulator stopped: no prompt within 0.5 simulated seconds "
             "(the line is still running); it had printed Error: made up")


def test_a_line_that_prints_an_error_and_runs_on_has_hit_the_line_limit(tmp_path):
    script = tmp_path / "runaway.script"
    script.write_text(RUNAWAY)
    r = harness("run", script, "--line-limit", "0.5")
    assert r.returncode == 1
    assert r.stderr.startswith(LIMIT_HIT.format(script=script) + " (in: LOOPY)\n"), r.stderr
    assert "2 3 + ." not in (tmp_path / "runaway.transcript").read_text()


def test_keep_going_stops_a_runaway_line_with_ctrl_c_and_goes_on(tmp_path):
    script = tmp_path / "runaway.script"
    script.write_text(RUNAWAY)
    r = harness("run", script, "--line-limit", "0.5", "--keep-going")
    assert r.returncode == 1
    assert r.stderr.startswith(LIMIT_HIT.format(script=script)
                               + "; ^C typed, the run goes on (in: LOOPY)\n"), r.stderr
    assert "3 of 3 steps run" in r.stdout
    assert (tmp_path / "runaway.transcript").read_text().endswith(
        "Error: interrupted by ^C: LOOPY\n2 3 + . 5  ok\n")


def test_keep_going_ends_when_not_even_ctrl_c_brings_the_prompt_back(tmp_path):
    """At processor priority 7 the DL11's receive interrupt (^C) is masked."""
    script = tmp_path / "deaf.script"
    script.write_text("7 PRIORITY! BEGIN AGAIN\n1 .\n")
    r = harness("run", script, "--line-limit", "0.5", "--keep-going")
    assert r.returncode == 1
    assert "^C typed, and still no prompt within 0.5 simulated seconds" in r.stderr
    assert "1 of 2 steps run" in r.stdout


def test_the_longest_script_line_is_what_the_kernels_accept_takes(tmp_path):
    """script.MAX_LINE, the docs' 255 and the kernel's TIB-SIZE - 1 agree, and a
    line that long is typed and answered whole."""
    assert MAX_LINE == read_kernel_map()["TIB-SIZE"] - 1 == 255
    assert "at most 255 characters" in (ROOT / "docs" / "console.md").read_text()
    line = "( " + "x" * (MAX_LINE - len("(  ) 7 .")) + " ) 7 ."
    assert len(line) == 255
    script = tmp_path / "long.script"
    script.write_text(line + "\n")
    r = harness("run", script)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "long.transcript").read_text().endswith(" 7  ok\n")


def test_a_simh_command_that_simh_refuses_fails_its_line(tmp_path):
    script = tmp_path / "s.script"
    script.write_text("1 .\n#simh show nosuchdevice\n2 .\n")
    r = harness("run", script)
    assert r.returncode == 1
    assert f"{script}:2: the simulator reported, during show nosuchdevice: " \
           "Non-existent device" in r.stderr
    transcript = (tmp_path / "s.transcript").read_text()
    assert transcript.endswith("1 . 1  ok\nsim> show nosuchdevice\nNon-existent device\n")


@pytest.mark.parametrize("args, message", [
    (["run", "NONE.script"], "NONE.script: cannot read the script"),
    (["run", "BAD.script"], "BAD.script:2: unknown directive #wiat"),
    (["run", "OK.script", "--disk", "NONE.dsk"], "NONE.dsk: no such disk image"),
    (["run", "OK.script", "--transcript", "NODIR/t"], "NODIR: no such directory"),
    (["run", "OK.script", "--out", "NODIR"], "NODIR: no such directory for OK.transcript"),
    (["run", "OK.script", "--out", "BAD.script"], "BAD.script: not a directory"),
    (["run", "OK.script", "--kernel", "NONE.lda"], "NONE.lda does not exist"),
    (["run", "OK.script", "--kernel", "BAD.script"], "BAD.map: No such file"),
])
def test_bad_input_is_a_clear_error_and_writes_nothing(tmp_path, args, message):
    (tmp_path / "BAD.script").write_text("1 .\n#wiat 2\n")
    (tmp_path / "OK.script").write_text("1 .\n")
    before = sorted(p.name for p in tmp_path.iterdir())
    r = harness(*[tmp_path / a if a[0].isupper() else a for a in args])
    assert r.returncode == 1
    assert message in r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_a_bad_option_is_a_usage_error(tmp_path):
    r = harness("run", tmp_path / "x.script", "--line-limit", "-3")
    assert r.returncode == 2 and "expected a positive number" in r.stderr


def test_an_unknown_option_prints_the_subcommands_usage(tmp_path):
    r = harness("run", tmp_path / "x.script", "--bogus")
    assert r.returncode == 2
    assert r.stderr.startswith("usage: python -m harness run ")
    assert "unrecognized arguments: --bogus" in r.stderr


def test_regress_help_states_the_exit_codes():
    r = harness("regress", "--help")
    assert r.returncode == 0
    assert "Exit status: 0 when every scenario" in " ".join(r.stdout.split())
