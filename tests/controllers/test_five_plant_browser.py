"""The lab's page of the five machines (harness/lab/controllers_page.py) in Debian's
headless Chromium, on a launched session (`make run CONTROLLERS=4 LAB=1`, at full
speed): the five machines' states and consoles, the servo table per axis updating
through a move, and the amplifier rack switched off and on at the 11/23's sim>.
make test-browser runs it (not make test); the screenshot is kept in
build/test-artifacts/controllers.png (and controllers-rack-off.png, the move waiting
on the rack)."""
import pytest
from selenium.webdriver.common.by import By

from harness.lab.launch import CHROMEDRIVER, CHROMIUM, have_browser, headless_browser
from harness.machine.build import PRISTINE_DISK, fresh_disk
from harness.machine.pty_child import probe_prompt
from tests.controllers.test_lockstep_launch import harness, leave
from tests.lab.labpage import ARTIFACTS, full_session, wait_for

pytestmark = full_session


# the page redraws twice a second: read it in one script, never through elements kept
def texts(page, selector):
    return page.execute_script(
        "return [...document.querySelectorAll(arguments[0])].map(e => e.textContent)", selector)


def servo(page):
    """The servo table: axis letter -> its cells."""
    rows = page.execute_script("return [...document.querySelectorAll('#servo tr')]"
                               ".map(r => [...r.cells].map(c => c.textContent))")
    return {cells[0]: cells for cells in rows if cells}


def rack(page):
    return page.execute_script("const r = document.getElementById('rack');"
                               "return [r.textContent, r.className]")


def test_the_page_of_the_five_shows_the_machines_the_servo_table_and_the_rack(tmp_path):
    if not have_browser():
        pytest.skip(f"needs Debian's chromium and chromium-driver ({CHROMIUM}, {CHROMEDRIVER})")
    disk = fresh_disk(tmp_path, "main.dsk", source=PRISTINE_DISK)
    session = tmp_path / "session"
    child = harness("controllers", "launch", "--fast", "--lab", "--busy-wait", "5",
                    "--disk", str(disk), "--session-dir", str(session))
    child.timeout = 120
    child.expect(r"the five machines' page: (http://127\.0\.0\.1:\d+/\?token=\S+)")
    url = child.match.group(1)
    child.expect(" ok\r\n")
    page = headless_browser()
    try:
        page.get(url)
        wait_for("the five machines", lambda: len(texts(page, ".machine h3")) == 5)
        assert "token=" not in page.current_url
        wait_for("the four servos booted", lambda: sum(
            "servo on axis" in t for t in texts(page, ".machine pre")) == 4, timeout=120)
        heads = texts(page, ".machine h3")
        assert heads[-1] == "PDP-11/23: running"
        assert heads[:4] == [f"LSI-11/03 {a}: running" for a in "xyzt"]
        assert sorted(servo(page)) == ["T", "X", "Y", "Z"]
        time_shown = page.find_element(By.ID, "time").text
        wait_for("the simulated time to move on",
                 lambda: page.find_element(By.ID, "time").text != time_shown)
        assert rack(page) == ["amplifier rack: on", ""]

        def at_sim(command):
            child.send("\x05")
            child.expect("sim> ")
            child.send(command + "\r")
            child.expect("sim> ")
            child.send("cont\r")
            assert probe_prompt(child) == 0

        for line in ("1200 LOAD", "Set.Up.Robot"):
            child.send(line + "\r")
            child.expect(" ok")
        at_sim("set plant power=off")
        wait_for("the page to show the rack off", lambda: rack(page) == [
            "amplifier rack: OFF (no axis is driven)", "off"])
        child.send("2000 1000 800 0 Abs.Move\r")
        child.expect(" ok")
        wait_for("the targets in the servo table", lambda: [servo(page)[a][1] for a in "XYZ"]
                 == ["2000", "1000", "800"])
        ARTIFACTS.mkdir(parents=True, exist_ok=True)
        page.save_screenshot(str(ARTIFACTS / "controllers-rack-off.png"))
        at_sim("set plant power=on")
        child.send("Move.Complete?\r")
        child.expect(" ok")
        wait_for("x's counter near its target", lambda: abs(int(servo(page)["X"][5]) - 2000) < 60)
        wait_for("the page to show the rack on", lambda: rack(page)[0] == "amplifier rack: on")
        page.save_screenshot(str(ARTIFACTS / "controllers.png"))
    finally:
        page.quit()
    assert leave(child) == 0
