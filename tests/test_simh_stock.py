"""SIMH's stock PDP-11 simulator, built from Debian's simh source, runs 11/23 code.

This is the reference the project's own simulator is measured against: if it
cannot run a two-instruction program, nothing else here can be trusted."""
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STOCK = ROOT / "build" / "pdp11-stock"


def test_stock_simulator_runs_a_program(tmp_path):
    # 1000: MOV #1234,R0 (012700 001234); 1004: HALT (000000)
    script = tmp_path / "t.ini"
    script.write_text(
        "set cpu 11/23\n"
        "deposit 1000 012700\ndeposit 1002 001234\ndeposit 1004 000000\n"
        "go 1000\nexamine r0\nquit\n"
    )
    out = subprocess.run([str(STOCK), str(script)], capture_output=True, text=True,
                         timeout=30).stdout
    assert "HALT instruction, PC: 001006" in out
    assert "R0:\t001234" in out
