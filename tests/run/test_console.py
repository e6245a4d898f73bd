"""The interactive console through a pty: boot, a command, SIMH's prompt and
back, and a clean exit that leaves an UPDATEd block on the disk."""
import shutil
import sys

import pexpect
import pytest

from harness.console_session import probe_prompt
from tests.run.common import PRISTINE, ROOT, needs_build

pytestmark = needs_build

BLOCK = 100


def console(disk, *extra):
    child = pexpect.spawn(sys.executable, ["-m", "harness", "console", "--fast",
                                           "--disk", str(disk), *extra],
                          cwd=str(ROOT), timeout=30, encoding="latin-1")
    child.delaybeforesend = None
    child.expect("Console: leave with BYE")
    child.expect(r"blocks 0-\d+\.\r\n ok\r\n")
    return child


def write_block_word(child, text):
    child.send(f': W S" {text}" {BLOCK} BLOCK SWAP CMOVE UPDATE ; W\r')
    child.expect(r" ok\r\n")


def block_text(disk, n):
    return disk.read_bytes()[1024 * n:1024 * n + 64]


def test_console_command_simh_prompt_and_bye_flushes(tmp_path):
    disk = tmp_path / "work.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = console(disk, "--trace", str(tmp_path / "t.csv"))
    child.send("1 2 + .\r")
    child.expect(r"1 2 \+ \. 3  ok\r\n")
    child.send("\x05")                                   # ^E: SIMH's prompt
    child.expect("sim> ")
    child.send("show plant\r")
    child.expect(r"PLANT, seed=\d+.*\r\n  X ")
    child.expect("sim> ")
    child.send("cont\r")
    assert probe_prompt(child) == 0
    child.send("6 7 * .\r")
    child.expect(r"6 7 \* \. 42  ok\r\n")
    write_block_word(child, "typed at the console")
    assert not block_text(disk, BLOCK).startswith(b"typed")  # still in a buffer
    child.send("BYE\r")
    child.expect(r"blocks flushed; disk .* detached\. Bye\.")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    assert block_text(disk, BLOCK).startswith(b"typed at the console")
    assert (tmp_path / "t.csv").read_text().startswith("time_s,axis,")


def test_ctrl_d_from_the_simh_prompt_also_flushes(tmp_path):
    disk = tmp_path / "work.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = console(disk)
    write_block_word(child, "left with control-D")
    child.send("\x05")
    child.expect("sim> ")
    child.send("\x04")                                   # ^D at sim>: leave all the same
    child.expect(r"blocks flushed; disk .* detached\. Bye\.")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    assert block_text(disk, BLOCK).startswith(b"left with control-D")


def test_missing_disk_is_a_clear_error(tmp_path):
    child = pexpect.spawn(sys.executable, ["-m", "harness", "console", "--disk",
                                           str(tmp_path / "none.dsk")],
                          cwd=str(ROOT), timeout=30, encoding="latin-1")
    child.expect(pexpect.EOF)
    child.close()
    assert "none.dsk: no such disk image" in child.before
    assert child.exitstatus == 1


def simh_command(child, command):
    """^E, one SIMH command, CONT; what the command printed."""
    child.send("\x05")
    child.expect("sim> ")
    child.send(command + "\r")
    child.expect("sim> ")
    printed = child.before
    child.send("cont\r")
    assert probe_prompt(child) == 0
    return printed


def test_readme_first_session_with_the_rack_switched_on_by_hand(tmp_path):
    disk = tmp_path / "work.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = console(disk)
    assert "power=off" in simh_command(child, "show plant")      # the console's boot
    for line in ("1000 LOAD", "Set.Up.Robot"):
        child.send(line + "\r")
        child.expect(r" ok\r\n", timeout=60)
    simh_command(child, "set plant power=on")
    child.send("800 800 0 0 Abs.Move Move.Complete?\r")
    child.expect(r"Move.Complete\?  ok\r\n", timeout=60)
    child.send("0 Read.Counter . 1 Read.Counter .\r")
    child.expect(r"Read.Counter \. (-?\d+) (-?\d+)  ok\r\n")
    assert all(abs(int(c) - 800) < 60 for c in child.match.groups())
    child.send("1020 LOAD\r")                                  # the demonstration block
    child.expect(r"1020 LOAD x y z t counters: .*\r\n(.*\r\n){3} ok\r\n", timeout=60)
    child.send("BYE\r")
    child.expect(pexpect.EOF)
