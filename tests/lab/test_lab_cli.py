"""python -m harness lab from the shell: bad input is one clear line and exit 1; a
simulator that dies under the lab ends it, saying so."""
import asyncio
import os
import signal
import socket
import subprocess
import sys

import pexpect

from harness.fuzz.paste_text import check_line, definitions, expected
from harness.cli import main
from harness.lab.launch import LabProcess
from harness.lab.page_client import Page
from harness.lab.protocol import MAX_KEYS
from harness.lab.session import remove_stale
from harness.machine import pty_child
from harness.machine.build import ROOT, fresh_disk
from tests.run.common import outlived


def lab(capsys, *args):
    """The lab command in this process: its exit status and what it wrote to stderr."""
    status = main(["lab", *args])
    return status, capsys.readouterr().err


def test_a_missing_disk_is_one_clear_line(tmp_path, capsys):
    status, err = lab(capsys, "--disk", str(tmp_path / "none.dsk"))
    assert status == 1 and "no such disk image" in err


def test_a_busy_port_is_one_clear_line(tmp_path, capsys):
    disk = fresh_disk(tmp_path)
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        status, err = lab(capsys, "--port", str(port), "--disk", str(disk))
    assert status == 1 and f"cannot serve on 127.0.0.1:{port}" in err


def test_a_simulator_that_dies_ends_the_lab(tmp_path):
    server = LabProcess(tmp_path)
    os.kill(server.simulator_pid(), signal.SIGKILL)
    assert server.proc.wait(timeout=30) == 1
    assert "the simulator exited on its own" in server.text()


def lab_in_a_terminal(tmp_path):
    """python -m harness lab on a pty (a shell's terminal), booted to the prompt;
    the child and its disk."""
    disk = fresh_disk(tmp_path)
    child = pexpect.spawn(sys.executable, ["-m", "harness", "lab", "--port", "0",
                                           "--speed", "full", "--disk", str(disk)],
                          cwd=str(ROOT), timeout=30, encoding="latin-1")
    child.expect(r"blocks 0-\d+\.\r+\n ok")
    return child, disk


def exit_status(child, timeout=30):
    """The lab on a terminal has printed its last line: its exit status, the pty
    closed without pexpect's fixed pause (pty_child.close)."""
    child.expect(pexpect.EOF, timeout=timeout)
    child.wait()
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


def test_sigterm_during_a_large_paste_flushes_and_exits_within_10_s(tmp_path):
    """Issue 23: the lab's loop never blocks, so a signal is acted on at once even
    while a paste of 20 000 characters waits at the 11/23's pace: FLUSH, the
    report, exit; the UPDATEd block is on the disk."""
    server = LabProcess(tmp_path, speed="real")
    text, _ = definitions(20000)

    async def paste():
        page = await Page.open(server)
        await page.send({"t": "take"})
        await page.type("300 BLOCK 1024 90 FILL UPDATE\r")
        for start in range(0, len(text), MAX_KEYS):
            await page.send({"t": "key", "d": text[start:start + MAX_KEYS]})
        await page.see("definition 2  ok")
        waiting = await page.until(lambda m: m["t"] == "data" and m["status"]["waiting"] > 0)
        await page.close()
        return waiting["status"]["waiting"]
    assert asyncio.run(paste()) > 10000                  # the page is told what waits
    server.proc.send_signal(signal.SIGTERM)
    assert server.proc.wait(timeout=10) == 0, server.text()
    assert "FLUSH answered ok" in server.text()
    assert "characters typed or pasted were still waiting" in server.text()
    assert server.disk.read_bytes()[300 * 1024:301 * 1024] == b"Z" * 1024, server.text()[-3000:]


def test_a_new_lab_removes_what_a_killed_lab_left(tmp_path):
    gone = subprocess.Popen(["true"])
    gone.wait()
    for name, pid in (("lab-killed", gone.pid), ("lab-running", os.getpid())):
        (tmp_path / name).mkdir()
        (tmp_path / name / "lab.pid").write_text(str(pid))
    (tmp_path / "lab-not-ours").mkdir()
    assert remove_stale(tmp_path) == ["lab-killed"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lab-not-ours", "lab-running"]


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
