"""SIMH's own devices still work in build/pdp11: the RL disk (needed to boot the
FORTH system) and the console keyboard, now polled at instruction-count pace."""
from programs import examine_results, results
from harness.machine import simh
import programs

PATTERN = [0o123456, 0o7, 0o177777, 0o52525]


def test_rl02_writes_and_reads_a_sector(tmp_path):
    disk = tmp_path / "scratch.dsk"
    prog = programs.rl_write_read()
    data = simh.deposit(0o3000, PATTERN) + simh.deposit(0o3776, [0o4321])
    out = simh.run(f"attach rl0 {disk}\n" + data + prog.script() + examine_results(1) +
                   "".join(f"examine {0o4000 + 2 * i:o}\n" for i in range(4)) + "examine 4776\n")
    assert "HALT instruction" in out
    ex = simh.examined(out)
    assert results(out, 1)[0] & 0o100000 == 0                     # no error
    assert [ex[f"{0o4000 + 2 * i:o}"] for i in range(4)] == PATTERN
    assert ex["4776"] == 0o4321
    assert disk.stat().st_size > 0


def test_console_input_is_never_lost_and_deterministic():
    text = "FORTH 1983"
    runs = []
    for _ in range(2):
        out = simh.run(programs.console_reader(len(text)).script() +
                       examine_results(len(text) // 2) + "examine tti pos\nexamine clk ticks\n",
                       keyboard=text)
        assert "HALT instruction" in out
        words = results(out, len(text) // 2)
        got = "".join(chr(w & 0o377) + chr(w >> 8) for w in words)
        assert got == text
        runs.append(out)
    assert runs[0] == runs[1]                 # the same instant, the same output
