"""The lab on the 11/23's clock (python -m harness lab --timed, make lab TIMED=1):
the page's clock button switches the time base between the instruction count and
the KDF11-A's instruction times (the LAB device's `clock` command, SET CLK TIMED),
simulated time running on continuously; SET CLK at the page's sim> shows in the
page too. (A lab on build/pdp11 refuses the button: test_sim_prompt_server.py.)"""
import asyncio

from harness.lab.page_client import Page

LAB_TIMED = True
TIMEOUT = 20


def status_where(page, wanted):
    """The next data message's status that `wanted` accepts."""
    return page.until(lambda m: m["t"] == "data" and wanted(m["status"]), TIMEOUT)


def test_the_clock_button_switches_the_time_base_and_time_runs_on(lab_server):
    async def run():
        page = await Page.open(lab_server)
        try:
            hello = next(m for m in page.messages if m["t"] == "hello")
            assert hello["status"]["clock"] == "timed" and hello["status"]["timable"]
            await page.send({"t": "take"})
            seen = []
            for clock in ("count", "timed", "count"):
                await page.send({"t": "clock", "v": clock})
                message = await status_where(page, lambda s, c=clock: s["clock"] == c)
                seen.append(message["status"]["time"])
            assert seen == sorted(seen) and seen[0] > 0          # on, never back
            await page.send({"t": "key", "d": "\x05show clk\r"})
            await page.see("rate=300000 instructions/s")          # the count, as the page says
            await page.send({"t": "key", "d": "set clk timed\r"})
            await status_where(page, lambda s: s["clock"] == "timed")   # SET CLK at sim> too
            await page.send({"t": "key", "d": "cont\r"})
            errors = [m["why"] for m in page.messages if m["t"] == "error"]
            assert not errors, errors
        finally:
            await page.close()
    asyncio.run(run())
