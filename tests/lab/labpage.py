"""Helpers of the lab's browser tests: waiting, and driving the page as a user."""
import os
import time

import pytest

from selenium.webdriver.common.by import By

from harness.machine.build import ROOT

ARTIFACTS = ROOT / "build" / "test-artifacts"

# The browser sessions are long checks: make test keeps a short one (the terminal, a
# move on the robot and the scope, both projector sizes, the sim> badge, BYE);
# make test-browser runs every session whole.
full_session = pytest.mark.skipif(not os.environ.get("LAB_BROWSER_FULL"),
                                  reason="the whole browser session runs with make test-browser")


def wait_for(what, condition, timeout=30, poll=0.05):
    """Poll condition() until it is true; its last value, or an AssertionError."""
    deadline = time.monotonic() + timeout
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(poll)


def js(page, expression):
    return page.execute_script(f"return {expression}")


def type_line(page, line, answer=" ok", timeout=60):
    """Type a line into the page's terminal; wait for its answer on the screen."""
    before = js(page, "window.lab.screen()").count(answer)
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").send_keys(line + "\n")
    wait_for(f"{line!r} to be answered",
             lambda: js(page, "window.lab.screen()").count(answer) > before, timeout)
    return js(page, "window.lab.screen()")


def click(page, selector):
    page.find_element(By.CSS_SELECTOR, selector).click()
