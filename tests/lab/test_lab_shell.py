"""python -m harness lab on a terminal: the shell that runs the lab is a console
too (the full SIMH console, a paste held whole), and every way the shell leaves
(BYE, its terminal closed, QUIT at sim>) FLUSHes first. (Apart from
test_lab_cli.py so that make test's workers run the two at once.)"""
import os
import sys

import pexpect

from harness.fuzz.paste_text import check_line, definitions, expected
from harness.machine import pty_child
from harness.machine.build import ROOT, fresh_disk
from harness.machine.pty_spawn import Spawn
from tests.run.common import outlived


def lab_in_a_terminal(tmp_path):
    """python -m harness lab on a pty (a shell's terminal), booted to the prompt;
    the child and its disk."""
    disk = fresh_disk(tmp_path)
    child = Spawn(sys.executable, ["-m", "harness", "lab", "--port", "0",
                                   "--speed", "full", "--disk", str(disk)],
                  cwd=str(ROOT), timeout=30, encoding="latin-1")
    child.expect(r"blocks 0-\d+\.\r+\n ok")
    return child, disk


def exit_status(child, timeout=30):
    """The lab on a terminal has printed its last line: its exit status, the pty
    closed without pexpect's fixed pause (pty_child.close)."""
    child.expect(pexpect.EOF, timeout=timeout)
    pty_child.close(child)
    return child.exitstatus


def test_the_shell_that_runs_the_lab_is_a_console_too(tmp_path):
    """On a terminal, the lab's shell types to the same FORTH as the page and shows
    what it prints; BYE typed there leaves as in make run (FLUSH, detach, exit 0)."""
    child, _ = lab_in_a_terminal(tmp_path)
    child.send("2 3 + .\r")
    child.expect(r"2 3 \+ \. 5  ok")
    child.send("BYE\r")
    child.expect("FLUSH answered ok")
    assert exit_status(child) == 0


def test_the_shell_keeps_the_full_simh_console(tmp_path):
    """The lab's own shell is not the page: at sim> it runs what the page may not
    (here `! echo`, a host shell command), its Enter ending the line there."""
    child, _ = lab_in_a_terminal(tmp_path)
    child.send("\x05")
    child.expect("sim> ")
    child.send("! echo shell-ran-$((6*7))\r")
    child.expect("shell-ran-42")
    child.expect("sim> ")
    child.send("cont\r")
    for _ in range(40):                       # what CONT's TCSAFLUSH may have eaten
        child.send("\r")
        if child.expect([r" ok\r", pexpect.TIMEOUT], timeout=0.25) == 0:
            break
    child.send("BYE\r")
    child.expect("FLUSH answered ok")
    assert exit_status(child) == 0


def test_closing_the_shells_terminal_leaves_with_flush(tmp_path):
    """The lab's terminal window closed (SIGHUP): FLUSH, detach, exit 0, the
    UPDATEd block on the disk."""
    child, disk = lab_in_a_terminal(tmp_path)
    child.send(': W S" kept by the lab" 100 BLOCK SWAP CMOVE UPDATE ; W\r')
    child.expect(r"W  ok")
    os.close(child.child_fd)
    assert not outlived(child), "the lab outlived its terminal"
    assert child.ptyproc.exitstatus == 0
    assert disk.read_bytes()[100 * 1024:100 * 1024 + 15] == b"kept by the lab"


def test_a_paste_into_the_shell_arrives_whole(tmp_path):
    """Issue 23: the lab's shell holds a paste as make run does."""
    child, _ = lab_in_a_terminal(tmp_path)
    text, n = definitions(1000)
    child.send(text + check_line() + "\r")
    child.expect(f"{expected(n)}  ok")
    assert "Error" not in child.before
    child.send("BYE\r")
    assert exit_status(child, timeout=60) == 0


def test_quit_edited_at_sim_in_the_shell_writes_the_block_first(tmp_path):
    """SIMH's QUIT typed in the lab's shell after ^W erased a word: the simulator
    FLUSHes the UPDATEd block before it ends (leave_check.c), and the lab exits 0."""
    child, disk = lab_in_a_terminal(tmp_path)
    child.send("300 BLOCK 1024 90 FILL UPDATE\r")
    child.expect(r"UPDATE  ok")
    child.send("\x05")
    child.expect("sim> ")
    child.send("xyz \x17quit\r")
    child.expect(r"QUIT: the FORTH's UPDATEd block\(s\) 300 were written to [^\r\n]* first")
    assert exit_status(child) == 0
    assert disk.read_bytes()[300 * 1024:301 * 1024] == b"Z" * 1024
