"""Every way out at the page's sim> writes the FORTH's UPDATEd blocks first
(issue 23): SIMH's QUIT typed, edited with the terminal's ^W, abbreviated or read
from a DO file, through the page's websocket; the simulator FLUSHes
(pdp11-devices/simh/leave_check.c), the lab reports it and exits 0. And the FORTH's BYE
word inside a line ends the lab as it ends make run."""
import asyncio
import contextlib
import json
import re

import aiohttp
import pytest

from harness.lab.launch import LabProcess

BLOCK = 300
BOOTED = r"blocks 0-\d+\.\r\n ok\r\n"
WAYS_OUT = {"typed": "quit\r", "^W-edited": "xyz \x17quit\r", "abbreviated": "q\r",
            "DO file": "do {do_file}\r"}


async def page_session(server, steps, timeout=60):
    """Type each (keys, expected regex) pair into the page's terminal, waiting (at
    most `timeout` wall seconds in all) for the console output to match before
    the next; the console text at the end."""
    deadline = asyncio.get_running_loop().time() + timeout
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(
                f"http://127.0.0.1:{server.port}/ws?token={server.token}",
                headers={"Origin": f"http://127.0.0.1:{server.port}"}) as ws:
            text = json.loads((await ws.receive(timeout=30)).data)["con"]   # hello
            # keys typed before the machine runs would be discarded (SIMH's GO
            # flushes the terminal's input): the FORTH's first prompt first
            for keys, expected in [("", BOOTED)] + steps:
                seen = 0 if not keys else len(text)
                if keys:
                    await ws.send_str(json.dumps({"t": "key", "d": keys}))
                while not re.search(expected, text[seen:]):
                    left = deadline - asyncio.get_running_loop().time()
                    if left <= 0:
                        raise AssertionError(f"no {expected!r} after {keys!r}: {text[-600:]!r}")
                    msg = await ws.receive(timeout=left)
                    if msg.type != aiohttp.WSMsgType.TEXT:
                        return text
                    message = json.loads(msg.data)
                    text += message.get("d", "") if message["t"] == "con" else ""
    return text


@contextlib.contextmanager
def lab(tmp_path):
    """A lab at full speed on a fresh disk; killed if a failing test leaves it running."""
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
            (f"{BLOCK} BLOCK 1024 90 FILL UPDATE\r", r"UPDATE  ok\r\n"),
            ("\x05", r"sim> $"),
            (keys, r"written to .* first|the BYE word")]))
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
            (f"{BLOCK} BLOCK 1024 90 FILL UPDATE\r", r"UPDATE  ok\r\n"),
            ("1 . BYE\r", r"Bye\.")]))
        assert server.proc.wait(timeout=60) == 0, server.text()
    assert "FLUSH answered ok" in server.text()
    assert (tmp_path / "robot.dsk").read_bytes()[BLOCK * 1024:(BLOCK + 1) * 1024] == b"Z" * 1024
