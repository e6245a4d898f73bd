"""Helpers of the lab's browser tests: waiting, and driving the page as a user."""
import time

from selenium.webdriver.common.by import By

from harness.machine.build import ROOT

ARTIFACTS = ROOT / "build" / "test-artifacts"


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
