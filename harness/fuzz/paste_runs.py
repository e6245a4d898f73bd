"""Pastes into the console and the lab (issue 23): every definition must arrive,
no error; the wall time each took.

    python -m harness.fuzz.paste_runs bench   (make bench-paste: 20 000 characters,
                                                full speed and the 11/23's pace)
    python -m harness.fuzz.paste_runs fuzz    (make fuzz: 5 000 and 30 000, both
                                                paces, the console and the lab page)

tests/run/test_console_paste.py pastes 1 000 in make test."""
import asyncio
import sys
import tempfile
import time

import pexpect

from harness.fuzz.paste_text import check_line, definitions, expected
from harness.lab.launch import LabProcess
from harness.lab.page_client import Page
from harness.machine import pty_child
from harness.machine.build import ROOT, fresh_disk
from harness.machine.pty_spawn import Spawn


class PasteFailed(AssertionError):
    pass


def console(disk, fast, timeout=30, idle_speed=1):
    """`python -m harness console` on `disk`, booted to its prompt; fast: --fast, its
    waits at `idle_speed` times the 11/23's pace."""
    child = Spawn(sys.executable, ["-m", "harness", "console", "--disk", str(disk)]
                  + (["--fast", "--idle-speed", str(idle_speed)] if fast else []),
                  cwd=str(ROOT), timeout=timeout, encoding="latin-1",
                  dimensions=(24, 200))
    child.delaybeforesend = child.delayafterread = None
    child.expect(r"blocks 0-\d+\.\r\n ok\r\n")
    return child


def console_paste(chars, fast, tmp, idle_speed=1):
    """Paste `chars` characters of definitions into the console in one write;
    (wall seconds until the check line answered, definitions)."""
    disk = fresh_disk(tmp, f"paste-{chars}.dsk")
    text, n = definitions(chars)
    child = console(disk, fast, idle_speed=idle_speed)
    log = []
    child.logfile_read = type("Log", (), {"write": lambda self, s: log.append(s),
                                          "flush": lambda self: None})()
    start = time.monotonic()
    child.send(text + check_line() + "\r")
    found = child.expect([f"{expected(n)}  ok", pexpect.TIMEOUT], timeout=max(60, chars / 100))
    seconds = time.monotonic() - start
    child.send("BYE\r")
    child.expect(pexpect.EOF, timeout=60)
    pty_child.close(child)
    screen = "".join(log)
    if found != 0 or "Error" in screen or "lost" in screen:
        raise PasteFailed(f"{chars} characters into the console ({'fast' if fast else 'real'})"
                          f": the screen ends {screen[-400:]!r}")
    return seconds, n


def lab_paste(chars, speed, tmp):
    """The same through the lab page's websocket, as the page sends a paste."""
    text, n = definitions(chars)
    server = LabProcess(tmp, speed=speed)

    async def paste():
        page = await Page.open(server)
        await page.send({"t": "take"})
        await page.until(lambda m: m["t"] == "keyboard" and m["you"])
        start, mark = time.monotonic(), len(page.screen)
        await page.type(text + check_line() + "\r", f"{expected(n)}  ok",
                        timeout=max(60, chars / 100))
        seconds = time.monotonic() - start
        if "Error" in page.screen[mark:] or "lost" in page.screen[mark:]:
            raise PasteFailed(f"{chars} characters into the lab ({speed}): "
                              f"{page.screen[-400:]!r}")
        await page.close()
        return seconds
    try:
        return asyncio.run(paste()), n
    finally:
        server.stop()


def report(where, chars, pace, seconds, n):
    print(f"  {where:8} {pace:10} {chars:6} characters ({n} definitions): {seconds:6.2f} s wall, "
          f"{chars / seconds:7.0f} characters/s", flush=True)


def main(argv):
    mode = argv[0] if argv else "bench"
    sizes = (20000,) if mode == "bench" else (5000, 30000)
    print(f"paste runs ({mode}): every definition arrives, no error; wall times on this "
          "host, under its present load")
    with tempfile.TemporaryDirectory() as tmp:
        try:
            for chars in sizes:
                for fast, pace in ((True, "full speed"), (False, "real pace")):
                    report("console", chars, pace, *console_paste(chars, fast, tmp))
                report("lab page", chars, "full speed", *lab_paste(chars, "full", tmp))
                if mode == "bench":
                    report("lab page", chars, "real pace", *lab_paste(chars, "real", tmp))
        except PasteFailed as failed:
            print(f"FAILED: {failed}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
