"""Every way out at the page's sim> writes the FORTH's UPDATEd blocks first
(issue 23): SIMH's QUIT typed, edited with the terminal's ^W, abbreviated or read
from a DO file, through the page's websocket; the simulator FLUSHes
(pdp11-devices/leave_check.c), the lab reports it and exits 0. And the FORTH's BYE
word inside a line ends the lab as it ends make run."""
import asyncio
import json
import re

import aiohttp
import pytest

from harness.lab.launch import LabProcess

BLOCK = 300
WAYS_OUT = {"typed": "quit\r", "^W-edited": "xyz \x17quit\r", "abbreviated": "q\r",
            "DO file": "do {do_file}\r"}


async def page_session(server, steps):
    """Type each (keys, expected regex) pair into the page's terminal, waiting for
    the console output to match before the next; the console text at the end."""
    text = ""
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(
                f"http://127.0.0.1:{server.port}/ws?token={server.token}",
                headers={"Origin": f"http://127.0.0.1:{server.port}"}) as ws:
            text = json.loads((await ws.receive(timeout=30)).data)["con"]   # hello
            for keys, expected in steps:
                seen = len(text)
                await ws.send_str(json.dumps({"t": "key", "d": keys}))
                while not re.search(expected, text[seen:]):
                    msg = await ws.receive(timeout=30)
                    if msg.type != aiohttp.WSMsgType.TEXT:
                        return text
                    message = json.loads(msg.data)
                    text += message.get("d", "") if message["t"] == "con" else ""
    return text


def leave_through_the_page(tmp_path, keys):
    server = LabProcess(tmp_path)
    disk = tmp_path / "robot.dsk"
    asyncio.run(page_session(server, [
        (f"{BLOCK} BLOCK 1024 90 FILL UPDATE\r", r"UPDATE  ok\r\n"),
        ("\x05", r"sim> $"),
        (keys, r"written to .* first|the BYE word")]))
    status = server.proc.wait(timeout=60)
    return status, server.text(), disk.read_bytes()[BLOCK * 1024:(BLOCK + 1) * 1024]


@pytest.mark.parametrize("way", WAYS_OUT)
def test_every_simh_way_out_at_the_page_writes_the_block_first(tmp_path, way):
    do_file = tmp_path / "leave.do"
    do_file.write_text("quit\n")
    status, log, block = leave_through_the_page(tmp_path, WAYS_OUT[way].format(do_file=do_file))
    assert status == 0, log
    assert "FLUSHed the FORTH's UPDATEd blocks first" in log
    assert block == b"Z" * 1024


def test_the_bye_word_inside_a_line_ends_the_lab_with_flush(tmp_path):
    server = LabProcess(tmp_path)
    asyncio.run(page_session(server, [
        (f"{BLOCK} BLOCK 1024 90 FILL UPDATE\r", r"UPDATE  ok\r\n"),
        ("1 . BYE\r", r"Bye\.")]))
    assert server.proc.wait(timeout=60) == 0, server.text()
    assert "FLUSH answered ok" in server.text()
    assert (tmp_path / "robot.dsk").read_bytes()[BLOCK * 1024:(BLOCK + 1) * 1024] == b"Z" * 1024
