"""Every way out at the page's sim> writes the FORTH's UPDATEd blocks first
(issue 23): SIMH's QUIT typed, edited with ^W or abbreviated, through the page's
websocket; the simulator FLUSHes (pdp11-devices/simh/leave_check.c), the lab
reports it and exits 0. (DO, which could read QUIT from a file, is refused at the
page's sim> since issue 18: tests/lab/test_sim_prompt_server.py.) And the FORTH's
BYE word inside a line ends the lab as it ends make run."""
import asyncio
import contextlib
import signal
import subprocess
import sys
import time

import pytest

from harness.lab.launch import LabProcess
from harness.lab.page_client import Page
from harness.machine.build import ROOT
from tests.process_ends import ended_within

BLOCK = 300
BOOTED = "blocks 0-10239.\r\n ok\r\n"
WAYS_OUT = {"typed": "quit\r", "^W-edited": "xyz \x17quit\r", "abbreviated": "q\r"}


async def page_session(server, steps):
    """Type each (keys, answer) into the page's terminal once the FORTH's first
    prompt is up (keys typed before the machine runs would be discarded), waiting
    for the screen to show `answer` before the next."""
    page = await Page.open(server)
    try:
        await page.see(BOOTED)
        for keys, answer in steps:
            before = page.screen.count(answer)
            await page.send({"t": "key", "d": keys})
            await page.see(answer, before)
    finally:
        await page.close()


@contextlib.contextmanager
def lab(tmp_path):
    """A lab (x10, LabProcess's) on a fresh disk; killed if a failing test leaves it running."""
    server = LabProcess(tmp_path)
    try:
        yield server
    finally:
        if server.proc.poll() is None:
            server.proc.kill()
            server.proc.wait()


def leave_through_the_page(tmp_path, keys):
    with lab(tmp_path) as server:
        asyncio.run(page_session(server, [
            (f"{BLOCK} BLOCK 1024 90 FILL UPDATE\r", "UPDATE  ok\r\n"),
            ("\x05", "sim> "),
            (keys, f"block(s) {BLOCK} were written to")]))
        status = server.proc.wait(timeout=60)
    block = (tmp_path / "robot.dsk").read_bytes()[BLOCK * 1024:(BLOCK + 1) * 1024]
    return status, server.text(), block


@pytest.mark.parametrize("way", WAYS_OUT)
def test_every_simh_way_out_at_the_page_writes_the_block_first(tmp_path, way):
    do_file = tmp_path / "leave.do"
    do_file.write_text("quit\n")
    status, log, block = leave_through_the_page(tmp_path, WAYS_OUT[way].format(do_file=do_file))
    assert status == 0, log
    assert "FLUSHed the FORTH's UPDATEd blocks first" in log
    assert block == b"Z" * 1024


def test_the_bye_word_inside_a_line_ends_the_lab_with_flush(tmp_path):
    with lab(tmp_path) as server:
        asyncio.run(page_session(server, [
            (f"{BLOCK} BLOCK 1024 90 FILL UPDATE\r", "UPDATE  ok\r\n"),
            ("1 . BYE\r", "Bye.")]))
        assert server.proc.wait(timeout=60) == 0, server.text()
    assert "FLUSH answered ok" in server.text()
    assert (tmp_path / "robot.dsk").read_bytes()[BLOCK * 1024:(BLOCK + 1) * 1024] == b"Z" * 1024


def test_a_late_ctrl_c_does_not_change_how_the_lab_ended(tmp_path):
    """^C keeps arriving (every 2 ms) from the BYE on: while the lab leaves it is the
    lab's own ^C (FLUSH, then leave), and once the simulator has ended it has nothing
    left to stop; the lab exits with its answer, 0, not by the signal."""
    server = LabProcess(tmp_path)

    async def bye():
        page = await Page.open(server)
        await page.see(BOOTED)
        await page.send({"t": "key", "d": "BYE\r"})
        await page.until(lambda m: m["t"] == "ended")
        await page.close()
    try:
        asyncio.run(bye())
        while server.proc.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                server.proc.send_signal(signal.SIGINT)
            time.sleep(0.002)
    finally:
        server.stop()
    assert server.proc.returncode == 0, server.text()[-2000:]
    assert "Traceback" not in server.text()


# A starter that dies without stop(): a lab, its URL waited for, the pids, then killed.
KILLED_STARTER = """
import os, sys
from pathlib import Path
from harness.lab.launch import LabProcess
server = LabProcess(Path(sys.argv[1]))
server.url
print(server.proc.pid, server.simulator_pid(), flush=True)
os.kill(os.getpid(), 9)
"""


def test_a_lab_ends_with_flush_when_the_process_that_started_it_is_killed(tmp_path):
    """A test or benchmark killed mid-run (SIGKILL, a CI timeout) once left its lab and
    simulator running at x10 for an hour: the lab now gets the ^C its starter would
    have sent (parent_death.py) and leaves as ^C leaves, FLUSH first."""
    starter = subprocess.run([sys.executable, "-c", KILLED_STARTER, str(tmp_path)], cwd=ROOT,
                             capture_output=True, text=True, timeout=60)
    assert starter.returncode == -signal.SIGKILL, starter.stderr
    lab_pid, simulator_pid = map(int, starter.stdout.split())
    assert ended_within([lab_pid, simulator_pid], 30), "the lab outlived its killed starter"
    log = (tmp_path / "lab.log").read_text()
    assert "FLUSH answered ok" in log and "Traceback" not in log, log
