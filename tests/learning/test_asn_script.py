"""The ASN (blocks 1070-1078) by scripted runs (python -m harness run), as
make asn-runs drives it: two runs of the same script write the same
trials.csv, byte for byte (a short version of make asn-runs' check). The first
is the start of conftest's `learned`, the run test_asn_robot.py's checks read
(the same runner in this process), the second `python -m harness run`."""
import subprocess
import sys

from harness.analysis import asn_log, asn_model
from harness.figures.asn_runs import LINE_LIMIT, script_text
from tests.learning.conftest import SCRIPT_TRIALS


def trials_csv(transcript):
    return asn_log.csv_text(asn_log.parse(transcript), asn_model.Params.from_blocks().goal_size)


def scripted_transcript(tmp_path, name, trials):
    script = tmp_path / f"{name}.script"
    script.write_text(script_text(trials))
    subprocess.run([sys.executable, "-m", "harness", "run", str(script), "--out",
                    str(tmp_path), "--line-limit", str(LINE_LIMIT)], check=True,
                   capture_output=True)
    return (tmp_path / f"{name}.transcript").read_text()


def test_two_runs_write_the_same_csv(learned, tmp_path):
    first = trials_csv(learned.transcript)
    second = trials_csv(scripted_transcript(tmp_path, "again", SCRIPT_TRIALS))
    assert first.startswith("trial,steps,") and len(first.splitlines()) == SCRIPT_TRIALS + 1
    assert first == second
