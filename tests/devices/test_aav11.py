"""AAV11-A D/A: 12-bit codes, read-back, byte writes, 2048 at power-up and INIT."""
from programs import examine_results, results
from harness.machine import simh
import programs


def test_aav11_bits_bytes_and_init():
    out = simh.run(programs.aav_bits().script() + examine_results(13) + "show aav11\n")
    assert "HALT instruction" in out
    assert results(out, 13) == [
        0o4000, 0o4000, 0o4000, 0o4000,   # power-up: 2048 on every channel
        0o7777,                           # bits 15:12 ignored, read as 0
        0o4125,                           # low byte written alone
        0o7525,                           # high byte alone (bits 15:12 dropped)
        0o1234, 0o4000,                   # channels are independent
        0o4000, 0o4000, 0o4000, 0o4000,   # bus INIT: 2048 again
    ]
    assert "X=2048 (+0.000 V) Y=2048 (+0.000 V) Z=2048 (+0.000 V) T=2048 (+0.000 V)" in out


def test_dac_writes_reach_the_plant():
    prog = programs.dac_step([0o4144, 0o3000, 0o4000, 0o7777])
    out = simh.run(prog.script(start=False) + "step 100\nshow plant\n")
    rows = {line.split()[0]: line.split() for line in out.splitlines()
            if line.startswith("  ") and line.split()[0] in "XYZT" and len(line.split()) > 10}
    assert [rows[a][5] for a in "XYZT"] == ["2148", "1536", "2048", "4095"]


def test_examine_reads_every_channel_of_the_register_table():
    """EXAMINE AAV11 DAC[n] (and the lab's front panel, which reads the same table)
    sees each channel: the table steps by the array's element size."""
    out = simh.run("deposit 17770442 1234\ndeposit 17770446 7777\n"
                   + "".join(f"examine aav11 dac[{i}]\n" for i in range(4)))
    assert [line.split()[-1] for line in out.splitlines() if "DAC[" in line] == \
        ["4000", "1234", "4000", "7777"]
