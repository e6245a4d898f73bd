"""Helpers of the lab's browser tests: waiting, and driving the page as a user."""
import asyncio
import json
import os
import threading
import time
from contextlib import contextmanager

import pytest

from selenium.webdriver.common.by import By

from harness.machine.build import BUILD, ROOT

ARTIFACTS = ROOT / "build" / "test-artifacts"
AXE = BUILD / "lab" / "node_modules" / "axe-core" / "axe.min.js"   # pinned: harness/lab/package.json

# The browser sessions are long checks: make test keeps a short one (the terminal, a
# move on the robot and the scope, both projector sizes, the sim> badge, BYE);
# make test-browser runs every session whole.
full_session = pytest.mark.skipif(not os.environ.get("LAB_BROWSER_FULL"),
                                  reason="the whole browser session runs with make test-browser")


def wait_for(what, condition, timeout=30, poll=0.05, seen=None):
    """Poll condition() until it is true; its last value, or an AssertionError
    (with what seen() returns then, to tell a slow host from a stuck lab). The first
    looks come sooner (10, 20, 40 ms): most waits are for the page's next frame."""
    deadline = time.monotonic() + timeout
    pause = min(poll, 0.01)
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}"
                                 + (f"; {seen()}" if seen else ""))
        time.sleep(pause)
        pause = min(poll, 2 * pause)


# until()'s looks in the page, as wait_for's from here (10, 20, 40, then every 50 ms;
# window.lab.screen() reads the whole scrollback), for at most `seconds` (a WebDriver
# script's own limit is 30 s: longer waits are several of these).
UNTIL = """const [seconds, done] = arguments, end = performance.now() + 1000 * seconds;
let error = null, pause = 10; %s
const look = () => {
  let value = null;
  try { value = (%s); } catch (e) { error = String(e); }
  if (value) done({value});
  else if (performance.now() > end) done({error});
  else { setTimeout(look, pause); pause = Math.min(50, 2 * pause); }
};
look();"""
UNTIL_CHUNK_S = 20


def until(page, what, expression, timeout=30, setup="", seen=None):
    """Wait in the page until a JavaScript expression is true (after `setup`'s
    statements, run once); its value, or an AssertionError as wait_for's. The page
    answers as soon as it holds, in one round trip: polled from here, each look is a
    round trip through chromedriver and a wait of up to 50 ms while the page draws."""
    script = UNTIL % (setup, expression)
    deadline = time.monotonic() + timeout
    while True:
        answer = page.execute_async_script(script, max(0.0, min(deadline - time.monotonic(),
                                                                UNTIL_CHUNK_S)))
        if answer.get("value"):
            return answer["value"]
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}"
                                 + (f" (the last look threw {answer['error']})"
                                    if answer.get("error") else "")
                                 + (f"; {seen()}" if seen else ""))


def js(page, expression):
    return page.execute_script(f"return {expression}")


def type_line(page, line, answer=" ok", timeout=60):
    """Type a line into the page's terminal; wait for its answer on the screen."""
    count = f"window.lab.screen().split({json.dumps(answer)}).length"
    before, keys = js(page, f"[{count}, document.querySelector('#terminal textarea')]")
    keys.send_keys(line + "\n")
    until(page, f"{line!r} to be answered", f"{count} > {before}", timeout)
    return js(page, "window.lab.screen()")


def click(page, selector):
    page.find_element(By.CSS_SELECTOR, selector).click()


def pace(page, speed):
    """The page's pace button (real, x10, full); wait until the lab runs at it."""
    click(page, f'#speeds button[data-speed="{speed}"]')
    until(page, f"{speed} pace", f"window.lab.status.speed === {json.dumps(speed)}")


def pause(page):
    """The page's Pause button; wait until the lab is paused (no data comes: the page
    draws only when its view changes)."""
    click(page, "#pause")
    until(page, "the pause", "window.lab.status.state === 'pause'")


def run(page):
    """Run again if the lab is paused (the Pause button then reads Run)."""
    if js(page, "window.lab.status.state") == "pause":
        click(page, "#pause")
        until(page, "the run", "window.lab.status.state === 'run'")


def connected(page):
    """Wait until the page has its websocket and the server's hello (the axes)."""
    until(page, "the page to connect",
          "window.lab && window.lab.connected && window.lab.perAxis.length > 0")


def serious_violations(page):
    """axe-core's serious and critical violations on the page as it is, with the
    elements they name."""
    if not page.execute_script("return typeof axe !== 'undefined'"):   # once per page load
        page.execute_script(AXE.read_text())
    page.set_script_timeout(60)
    return page.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "axe.run(document, { resultTypes: ['violations'] }).then((r) => done(r.violations"
        ".filter((v) => ['serious', 'critical'].includes(v.impact))"
        ".map((v) => [v.id, v.nodes.map((n) => n.target.join(' ')).slice(0, 8)])));")


@contextmanager
def projector(page, width, height):
    """The page in a window of a projector's size (Chromium's device metrics)."""
    page.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                         {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
    try:
        until(page, "the layout", f"window.innerWidth === {width}")
        yield
    finally:
        page.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})


def assert_on_screen(page, width, height, panels, buttons="header button"):
    """After a relayout: nothing scrolls, each panel is sizeable and inside the window,
    no button of `buttons` (a CSS selector) is cut off at the right, and the terminal
    is drawn inside its box."""
    drawn = page.execute_script("window.dispatchEvent(new Event('resize'));"
                                "return window.lab.frames || 0")
    until(page, "the page drawn again after the relayout", f"window.lab.frames > {drawn}")
    scroll = js(page, "[document.documentElement.scrollWidth, document.documentElement.scrollHeight]")
    assert scroll[0] <= width and scroll[1] <= height, scroll
    for panel in panels:
        box = js(page, f"document.getElementById('{panel}').getBoundingClientRect().toJSON()")
        assert box["width"] > 200 and box["height"] > 150, (panel, box)
        assert box["right"] <= width and box["bottom"] <= height, (panel, box)
    rights = js(page, f"[...document.querySelectorAll('{buttons}')]"
                      ".map(b => b.getBoundingClientRect().right)")
    assert max(rights) <= width, "a button is cut off"
    frames(page)
    assert not terminal_spills(page), terminal_spills(page)


def frames(page, n=3):
    """Wait for n of the page's animation frames: what a resize observer asked is done."""
    page.execute_async_script("const done = arguments[0]; let n = %d;"
                              "const f = () => --n ? requestAnimationFrame(f) : done();"
                              "requestAnimationFrame(f);" % n)


def terminal_spills(page):
    """What is wrong with the terminal's drawn screen (xterm.js's) where it is: out of its
    box, over another panel, the console panel or the page scrolling; [] when nothing."""
    return js(page, """(() => {
      const box = (e) => e.getBoundingClientRect(), wrong = [];
      const screen = box(document.querySelector('#terminal .xterm-screen'));
      const term = box(document.getElementById('terminal'));
      if (screen.bottom > term.bottom + 0.5 || screen.right > term.right + 0.5)
        wrong.push(`the screen ends at ${screen.right}, ${screen.bottom}; its box at `
                   + `${term.right}, ${term.bottom}`);
      for (const panel of document.querySelectorAll('main > .panel:not([hidden])')) {
        const p = box(panel);
        if (panel.id !== 'console-panel' && screen.left < p.right && p.left < screen.right
            && screen.top < p.bottom && p.top < screen.bottom) wrong.push(`over ${panel.id}`);
      }
      const con = document.getElementById('console-panel'), doc = document.documentElement;
      if (con.scrollHeight > con.clientHeight) wrong.push('the console panel overflows');
      if (doc.scrollWidth > innerWidth || doc.scrollHeight > innerHeight) wrong.push('the page scrolls');
      return wrong; })()""")


class AnotherPage:
    """A second page (a websocket, in a thread of its own) that takes the keyboard."""

    def __init__(self, server):
        from harness.lab.page_client import Page      # aiohttp: for the few tests that use it
        self.loop = asyncio.new_event_loop()
        threading.Thread(target=self.loop.run_forever, daemon=True).start()
        self.page = self.run(Page.open(server))
        self.run(self.page.send({"t": "take"}))

    def run(self, coroutine):
        return asyncio.run_coroutine_threadsafe(coroutine, self.loop).result(30)

    def close(self):
        self.run(self.page.close())
        self.loop.call_soon_threadsafe(self.loop.stop)
