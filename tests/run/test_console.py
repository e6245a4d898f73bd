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


def expect_left_with_flush(child, disk, text):
    """The console flushed, detached, exited 0, and the block holds text."""
    child.expect(r"blocks flushed; disk .* detached\. Bye\.")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    assert block_text(disk, BLOCK).startswith(text)


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
    expect_left_with_flush(child, disk, b"typed at the console")
    assert (tmp_path / "t.csv").read_text().startswith("time_s,axis,")


def test_ctrl_d_from_the_simh_prompt_also_flushes(tmp_path):
    disk = tmp_path / "work.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = console(disk)
    write_block_word(child, "left with control-D")
    child.send("\x05")
    child.expect("sim> ")
    child.send("\x04")                                   # ^D at sim>: leave all the same
    expect_left_with_flush(child, disk, b"left with control-D")


def test_missing_disk_is_a_clear_error(tmp_path):
    child = pexpect.spawn(sys.executable, ["-m", "harness", "console", "--disk",
                                           str(tmp_path / "none.dsk")],
                          cwd=str(ROOT), timeout=30, encoding="latin-1")
    child.expect(pexpect.EOF)
    child.close()
    assert "none.dsk: no such disk image" in child.before
    assert child.exitstatus == 1


def test_bye_inside_a_definition_leaves_like_typed_bye(tmp_path):
    """The FORTH's BYE word halts the simulator at (BYE); the console sees the
    halt, continues the FORTH, FLUSHes and detaches as for a typed BYE."""
    disk = tmp_path / "work.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = console(disk)
    write_block_word(child, "left by the BYE word")
    child.send(": LEAVE-NOW 1 . BYE ; LEAVE-NOW\r")
    expect_left_with_flush(child, disk, b"left by the BYE word")
