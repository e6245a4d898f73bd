"""A longer browser session (make test-lab-long; skipped in make test): the blocks
loaded at the 11/23's real pace, a page reload that keeps the console and the
token, Freeze, SIMH's sim> from the page, and the servo table emptied by FORGET."""
import os

import pytest
from selenium.webdriver.common.by import By

from labpage import click, js, type_line, wait_for

LAB_SPEED = "x10"                  # see test_browser.py
pytestmark = pytest.mark.skipif(not os.environ.get("LAB_LONG"),
                                reason="the long lab session runs with make test-lab-long")


@pytest.fixture(scope="module")
def page(lab_server, browser):
    browser.get(lab_server.url)
    wait_for("the page", lambda: js(browser, "window.lab && window.lab.connected"))
    click(browser, '#speeds button[data-speed="real"]')
    return browser


def test_blocks_load_at_real_pace(page):
    wait_for("real pace", lambda: js(page, "window.lab.status.speed") == "real")
    assert js(page, "Object.keys(window.lab.servo).length") == 0
    assert "Error" not in type_line(page, "1000 LOAD", timeout=300)
    type_line(page, "Set.Up.Robot")
    click(page, "#power")
    wait_for("the amplifiers on", lambda: js(page, "window.lab.status.power") == "on")
    type_line(page, "800 0 0 0 Abs.Move")
    wait_for("x near 800", lambda: abs(js(page, "window.lab.latest[0][6]") - 800) < 60, 60)


def test_a_reload_keeps_the_console_and_the_session(page, lab_server):
    page.refresh()
    wait_for("the page again", lambda: js(page, "window.lab && window.lab.connected"))
    assert "800 0 0 0 Abs.Move" in js(page, "window.lab.screen()")
    assert "2  ok" in type_line(page, "1 1 + .")


def test_freeze_holds_the_scope_while_the_run_goes_on(page):
    click(page, "#freeze")
    frozen = js(page, "window.lab.scope.view")
    start = js(page, "window.lab.status.time")
    wait_for("time to go on", lambda: js(page, "window.lab.status.time") > start + 0.5)
    assert js(page, "window.lab.scope.view") == frozen
    click(page, "#freeze")
    assert js(page, "window.lab.scope.frozen") is None


def test_sim_prompt_from_the_page(page):
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").send_keys("\x05")
    wait_for("sim>", lambda: js(page, "window.lab.screen()").rstrip().endswith("sim>"))
    type_line(page, "show lab", answer="LAB, running")
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").send_keys("cont\n")
    assert "3  ok" in type_line(page, "1 2 + .", timeout=30)


def test_forget_empties_the_servo_table(page):
    assert "Desire.Pos" in js(page, "window.lab.servo")
    type_line(page, "FORGET Desire.Pos")
    wait_for("the table to empty", lambda: js(page, "Object.keys(window.lab.servo).length") == 0)
