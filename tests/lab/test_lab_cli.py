"""python -m harness lab from the shell: bad input is one clear line and exit 1; a
simulator that dies under the lab ends it, saying so; SIGTERM during a paste
FLUSHes and exits. (The lab on a terminal, its shell a console too:
test_lab_shell.py.)"""
import asyncio
import os
import signal
import socket
import subprocess

from harness.fuzz.paste_text import definitions
from harness.cli import main
from harness.lab.launch import LabProcess
from harness.lab.page_client import Page
from harness.lab.protocol import MAX_KEYS
from harness.lab.session import remove_stale
from harness.machine.build import fresh_disk


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
