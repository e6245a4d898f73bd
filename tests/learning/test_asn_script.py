"""The ASN (blocks 1070-1078) by scripted runs (python -m harness run), as
make asn-runs drives it: two runs of the same script write the same
trials.csv, byte for byte (a short version of make asn-runs' check)."""
import subprocess
import sys

from harness.analysis import asn_log, asn_model
from harness.figures.asn_runs import LINE_LIMIT, script_text


def scripted_csv(tmp_path, name, trials):
    script = tmp_path / f"{name}.script"
    script.write_text(script_text(trials))
    subprocess.run([sys.executable, "-m", "harness", "run", str(script), "--out",
                    str(tmp_path), "--line-limit", str(LINE_LIMIT)], check=True,
                   capture_output=True)
    text = (tmp_path / f"{name}.transcript").read_text()
    return asn_log.csv_text(asn_log.parse(text), asn_model.Params.from_blocks().goal_size)


def test_two_runs_write_the_same_csv(tmp_path):
    first, second = (scripted_csv(tmp_path, name, 2) for name in ("one", "two"))
    assert first.startswith("trial,steps,") and len(first.splitlines()) == 3
    assert first == second
