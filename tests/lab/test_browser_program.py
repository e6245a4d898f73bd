"""The program pane and the lessons in Debian's headless Chromium, as a teacher would
use them: the block being loaded shown with its listing and the line the machine
stopped in; a block edited in the page, typed at the FORTH, FLUSHed and found on
the disk image; a lesson's line typed by its button; an exercise's check run; the
light theme and the largest text fit both projector sizes. Screenshots in
build/test-artifacts/lab-program-*.png and lab-teach-*.png."""
import pytest
from selenium.webdriver.common.by import By

from harness.analysis.listing import BLOCK_BYTES

from labpage import ARTIFACTS, AnotherPage, assert_on_screen, click, connected, full_session, \
    js, pace, projector, serious_violations, type_line, wait_for

pytestmark = full_session

LAB_SPEED = "real"                  # loading 1000-1012 takes seconds: time to pause in it
EDITED = 200                        # a blank block of the pristine disk


@pytest.fixture(scope="module")
def page(lab_server, browser):
    browser.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})
    browser.get(lab_server.url)
    browser.execute_script("localStorage.clear()")
    browser.refresh()
    connected(browser)
    yield browser
    browser.get("about:blank")      # as test_browser.py's page: nothing left ticking


def shown_lines(page):
    return js(page, "[...document.querySelectorAll('#program-text .pl-text')]"
                    ".map(e => e.textContent)")


def test_the_pane_follows_the_load_and_marks_the_line_it_stopped_in(page):
    click(page, '#views button[data-view="program-panel"]')
    assert js(page, "document.getElementById('robot-panel').hidden")
    # at the 11/23's own pace blocks 1002-1012 take some 3 s to load, not 0.3 s at
    # x10: the Pause still comes while they load on a host busy with other tests
    pace(page, "real")
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").send_keys("1000 LOAD\n")
    # the page clicks Pause itself the moment its front panel shows block 1002
    # loading: a poll through Selenium on a host busy with other browser tests has
    # come later than the end of the load
    page.set_script_timeout(60)
    page.execute_async_script("""
      const done = arguments[0];
      const look = () => {
        const loading = window.lab.panel && window.lab.panel.loading;
        if (loading && loading.block >= 1002) { document.getElementById('pause').click(); done(); }
        else setTimeout(look, 5);
      };
      look();""")
    wait_for("the pause", lambda: js(page, "window.lab.status.state") == "pause")
    wait_for("the badge (the page draws with the robot hidden)",
             lambda: page.find_element(By.ID, "state").text == "PAUSED")
    where = js(page, "window.lab.panel.loading")
    assert where, "the load ended before the pause: nothing to mark"
    wait_for("the pane to show that block",
             lambda: js(page, "window.lab.program.block") == where["block"])
    current = wait_for("the line marked", lambda: page.find_elements(
        By.CSS_SELECTOR, "#program-text .pl.current"))
    assert len(current) == 1 and int(current[0].get_attribute("data-line")) == where["line"]
    assert f"stopped in block {where['block']}, line {where['line']}" in \
        page.find_element(By.ID, "program-where").text
    code = js(page, "window.lab.program.code")       # the listing's rows, line by line
    assert sum(map(len, code)) > 5 and all(r.strip()[:6].isdigit() for rows in code for r in rows)
    page.save_screenshot(str(ARTIFACTS / "lab-program-stopped.png"))
    click(page, "#pause")                            # Run: the load goes on
    pace(page, "x10")
    wait_for("1000 LOAD's ok", lambda: "ok" in js(page, "window.lab.screen()").split(
        "1000 LOAD", 1)[1], timeout=120)
    assert not page.find_elements(By.CSS_SELECTOR, "#program-text .pl.current")


def test_a_block_listed_by_number_shows_what_each_line_laid_down(page):
    field = page.find_element(By.ID, "program-block")
    field.clear()
    field.send_keys("1006\n")
    wait_for("block 1006", lambda: js(page, "window.lab.program.block") == 1006)
    lines, code = shown_lines(page), js(page, "window.lab.program.code")
    assert "Velocity" in lines[7] and any("Velocity" in row for row in code[7])
    assert "Velocity" in page.find_element(By.ID, "program-text").text


def test_a_block_edited_in_the_page_is_typed_at_the_forth_and_flushed(page, lab_server):
    field = page.find_element(By.ID, "program-block")
    field.clear()
    field.send_keys(f"{EDITED}\n")
    wait_for("the blank block", lambda: js(page, "window.lab.program.why") == f"block {EDITED} is blank")
    click(page, "#program-edit")
    inputs = page.find_elements(By.CSS_SELECTOR, "#program-lines input")
    assert len(inputs) == 16 and inputs[0].get_attribute("maxlength") == "64"
    title = "( squares, typed in the lab page )"
    body = ": SQUARE ( n -- n*n )  DUP * ;"
    inputs[0].send_keys(title)
    inputs[1].send_keys(body)
    page.save_screenshot(str(ARTIFACTS / "lab-program-editor.png"))
    other = AnotherPage(lab_server)                  # the one-keyboard rule
    try:
        wait_for("the other page to hold the keyboard",
                 lambda: js(page, "window.lab.keyboard.holder") and not js(
                     page, "window.lab.keyboard.you"))
        click(page, "#program-update")
        note = page.find_element(By.ID, "program-note").text
        assert "holds the keyboard: take it to type here" in note, note
        assert "P ( squares" not in js(page, "window.lab.screen()")   # nothing typed
    finally:
        other.close()
    wait_for("the keyboard free", lambda: js(page, "window.lab.keyboard.holder") is None)
    before = js(page, "window.lab.screen()").count(" ok")
    click(page, "#program-update")                   # nobody holds it: the page takes it
    wait_for("the editor's lines to be answered",
             lambda: js(page, "window.lab.screen()").count(" ok") >= before + 4)
    screen = js(page, "window.lab.screen()")
    assert f"1 P {body}" in screen and "Error" not in screen
    on_disk = lab_server.disk.read_bytes()[EDITED * BLOCK_BYTES:][:BLOCK_BYTES]
    assert title.encode() not in on_disk             # UPDATEd, not yet written
    click(page, "#program-flush")
    wait_for("the disk to hold the block", lambda: lab_server.disk.read_bytes()[
        EDITED * BLOCK_BYTES:][:128].startswith(title.ljust(64).encode() + body.encode()))
    wait_for("the pane to read it back",
             lambda: shown_lines(page)[1].strip() == f"1 {body}", timeout=20)
    assert f"{EDITED} LOAD  7 SQUARE . 49" in type_line(page, f"{EDITED} LOAD  7 SQUARE .")


def test_a_lesson_types_its_line_and_an_exercise_runs_its_check(page):
    click(page, '#views button[data-view="teach-panel"]')
    assert page.find_element(By.ID, "teach-panel").is_displayed()
    steps = page.find_elements(By.CSS_SELECTOR, "#teach-body li")
    assert len(steps) == 6 and "1000 LOAD" in steps[0].text       # README's first session
    before = js(page, "window.lab.screen()").count("Read.Counter")
    page.find_elements(By.CSS_SELECTOR, "#teach-body .teach-do")[4].click()
    wait_for("the lesson's line typed", lambda: js(page, "window.lab.screen()")
             .count("0 Read.Counter . 1 Read.Counter .") > before)
    # imported here: it loads selenium's whole WebDriver (0.3 CPU-s), which every
    # make test worker would pay at collection for a test only make test-browser runs
    from selenium.webdriver.support.ui import Select
    Select(page.find_element(By.ID, "teach-lesson")).select_by_index(2)
    assert "missing ELSE" in page.find_element(By.ID, "teach-body").text or \
        "ramp" in page.find_element(By.ID, "teach-body").text
    click(page, "#teach-check")
    text = wait_for("exercise 2's check", lambda: (js(page, "window.lab.checks[2]") or {})
                    .get("text"), timeout=240)
    assert js(page, "window.lab.checks[2].ok") is True
    assert "$ python -m harness tick --ticks 8" in text and "Velocity" in text
    assert "Velocity" in page.find_element(By.ID, "teach-measured").text


@pytest.mark.parametrize("theme", ["dark", "light"])
@pytest.mark.parametrize("width, height", [(1280, 720), (1920, 1080)])
def test_the_teaching_views_fit_both_projectors_in_both_themes(page, theme, width, height):
    """No scrolling with the lessons or the program shown, in both themes, at the
    largest text; the panes scroll inside themselves. axe-core: nothing serious."""
    if js(page, "window.lab.theme") != theme:
        click(page, "#theme")
    sizes = ("[term.options.fontSize, parseFloat(getComputedStyle(document.querySelector("
             "'#servo th')).fontSize), parseFloat(getComputedStyle(document.getElementById("
             "'front-panel')).fontSize), window.lab.scope.plot.axes[1].font[0]]")
    while not js(page, "document.getElementById('font-down').disabled"):
        click(page, "#font-down")
    smallest = js(page, sizes)
    for _ in js(page, "window.lab.fontScales"):
        if not js(page, "document.getElementById('font-up').disabled"):
            click(page, "#font-up")
    assert js(page, "window.lab.fontStep") == len(js(page, "window.lab.fontScales")) - 1
    largest = js(page, sizes)                # the terminal, the servo table, the front
    assert all(float(str(b).split("px")[0]) > float(str(a).split("px")[0])   # panel, the
               for a, b in zip(smallest, largest)), (smallest, largest)     # scope's axes
    with projector(page, width, height):
        for view in ("teach-panel", "program-panel"):
            click(page, f'#views button[data-view="{view}"]')
            assert_on_screen(page, width, height, (view, "console-panel", "servo-panel",
                                                   "scope-panel"),
                             buttons="header button, #views button")
            page.save_screenshot(str(ARTIFACTS / f"lab-{view.split('-')[0]}-{theme}-{width}.png"))
            violations = serious_violations(page)
            assert not violations, violations
