"""Keys in the lab (issue 23), over the page's websocket: one keyboard per lab, a
paste arrives whole, every malformed message gets one error and changes nothing,
and the FORTH's BYE word inside a line ends the lab as it ends make run."""
import asyncio
import random

from harness.fuzz.paste_text import check_line, definitions, expected
from harness.fuzz.protocol_fuzz import bad_message
from harness.lab.page_client import Page

FUZZ_MESSAGES = 2000          # make fuzz sends 50 000 (harness/fuzz/protocol_fuzz.py)


def run(coroutine):
    return asyncio.run(coroutine)


def test_two_pages_typing_at_once_never_mix(lab_server):
    async def both():
        one, two = await Page.open(lab_server), await Page.open(lab_server)
        await asyncio.gather(one.send({"t": "key", "d": ": aa1 111 ;\r"}),
                             two.send({"t": "key", "d": ": bb2 222 ;\r"}))
        first = await one.until(lambda m: m["t"] in ("input", "error"))
        second = await two.until(lambda m: m["t"] in ("input", "error"))
        assert sorted([first["t"], second["t"]]) == ["error", "input"]    # one holds it
        holder, watcher = (one, two) if first["t"] == "input" else (two, one)
        refused = first if first["t"] == "error" else second
        assert "holds the keyboard" in refused["why"]
        await holder.see(" ok")
        told = [m for m in watcher.messages if m["t"] == "keyboard"]
        assert told and told[-1]["holder"].startswith("page ") and not told[-1]["you"]
        await watcher.send({"t": "take"})                  # one click
        await watcher.until(lambda m: m["t"] == "keyboard" and m["you"])
        await holder.until(lambda m: m["t"] == "keyboard" and not m["you"])
        line = ": bb2 222 ;\r" if watcher is two else ": aa1 111 ;\r"
        await watcher.type(line)
        screen = await watcher.type("aa1 . bb2 .\r", "111 222  ok")
        assert "Error" not in screen[screen.index(": aa1") - 20 if ": aa1" in screen else 0:]
        await one.close()
        await two.close()
    run(both())


def test_a_paste_through_the_page_arrives_whole(lab_server):
    text, n = definitions(5000)

    async def paste():
        page = await Page.open(lab_server)
        await page.send({"t": "take"})
        await page.until(lambda m: m["t"] == "keyboard" and m["you"])
        start = len(page.screen)
        await page.type(text + check_line() + "\r", f"{expected(n)}  ok")
        assert "Error" not in page.screen[start:] and "lost" not in page.screen[start:]
        await page.close()
    run(paste())


def test_malformed_messages_get_one_error_each_and_change_nothing(lab_server):
    async def fuzz():
        page = await Page.open(lab_server)
        speed = page.messages[0]["status"]["speed"]
        rng = random.Random(23)
        for _ in range(FUZZ_MESSAGES):
            await page.send(bad_message(rng))
        await page.until(lambda m: page.count.get("error", 0) >= FUZZ_MESSAGES, 60)
        await page.send({"t": "take"})
        await page.type("2 3 + .\r", "5  ok")                  # the socket is still open
        statuses = [m["status"] for m in page.messages if m["t"] == "data"]
        assert all(s["speed"] == speed for s in statuses)
        assert sum(m["t"] == "error" for m in page.messages) == FUZZ_MESSAGES
        await page.close()
    run(fuzz())
    assert "Traceback" not in lab_server.text()


def test_the_bye_word_inside_a_line_ends_the_lab(lab_server):
    async def bye():
        page = await Page.open(lab_server)
        await page.send({"t": "take"})
        await page.until(lambda m: m["t"] == "keyboard" and m["you"])
        await page.send({"t": "key", "d": "300 BLOCK 1024 90 FILL UPDATE 1 . BYE\r"})
        ended = await page.until(lambda m: m["t"] == "ended")
        assert ended["safe"] is True
        await page.close()
    run(bye())
    assert lab_server.proc.wait(timeout=60) == 0
    assert "the BYE word: leaving" in lab_server.text()
    assert "FLUSH answered ok" in lab_server.text()
