"""The console's hint when the PDP-11 stops by itself (harness/machine/console_halt.py)."""

from harness.machine.console_halt import HaltWatcher
from harness.machine.kernel_layout import entry as kernel_entry
from harness.machine.machine import SIMULATOR
from harness.machine.build import KERNEL, MACHINE_INI
from harness.machine.pty_spawn import Spawn


def test_a_halt_gets_a_hint_in_pieces():
    w = HaltWatcher("build/kernel.lda", 0o56424)
    assert w.feed(b"0 2000 0 FILL \r\nHALT instr") == b"0 2000 0 FILL \r\nHALT instr"
    out = w.feed(b"uction, PC: 002002 (HALT)\r\nsim> ")
    assert b"[console] The PDP-11 stopped by itself (HALT instruction at 002002)" in out
    assert b"LOAD build/kernel.lda then RUN 56424" in out
    assert out.endswith(b"sim> ")


def test_control_e_and_ordinary_output_get_none():
    w = HaltWatcher("k", 1)
    for data in (b"\r\nSimulation stopped, PC: 002002 (MOV R0,R1)\r\nsim> ", b"1 2 + . 3  ok\r\n",
                 b"sim> show clk\r\n"):
        assert w.feed(data) == data


def test_kernel_entry_from_the_map(tmp_path):
    assert kernel_entry(KERNEL.with_suffix(".map")) > 0o2000
    assert kernel_entry(tmp_path / "none.map") is None


def test_the_real_halt_line_matches(tmp_path):
    """What SIMH prints for a FORTH whose kernel was zeroed: the hint follows."""
    ini = tmp_path / "h.ini"
    ini.write_text(f"do {MACHINE_INI}\nload {KERNEL}\ngo\n")
    child = Spawn(str(SIMULATOR), [str(ini)], timeout=20)
    try:
        child.expect(b" ok\r\n")
        child.send(b"1024 2000 0 FILL\r")   # from 2000 octal: the kernel's code (below it: refused)
        child.expect(b"sim> ")
        w = HaltWatcher("k", 1)
        assert b"stopped by itself (HALT instruction" in w.feed(child.before + b"sim> ")
    finally:
        child.close(force=True)
