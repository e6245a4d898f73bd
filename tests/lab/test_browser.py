"""The lab page in Debian's headless Chromium (Selenium with chromium-driver), as a
user would drive it: the terminal answers, the blocks load, a move shows in the
robot drawing and on the scope, pause holds simulated time, step is one tick,
BYE leaves. The screenshot is kept in build/test-artifacts/lab.png."""
import pytest
from selenium.webdriver.common.by import By

from harness.analysis.trace import parse_rows
from harness.machine.plant_rows import COLUMNS

from labpage import ARTIFACTS, click, js, type_line, wait_for

# The lab boots with the amplifier rack off, as make run does: nothing drifts until
# the page's switch is turned on after Set.Up.Robot. x10 keeps the run short.
LAB_SPEED = "x10"


@pytest.fixture(scope="module")
def page(lab_server, browser):
    browser.get(lab_server.url)
    wait_for("the page to connect", lambda: browser.execute_script(
        "return window.lab && window.lab.connected && window.lab.perAxis.length > 0"))
    return browser


def test_the_terminal_answers(page):
    assert "2 3 + . 5  ok" in type_line(page, "2 3 + .")
    assert "token=" not in page.current_url          # off the address bar


def test_a_move_shows_on_the_robot_and_the_scope(page):
    screen = type_line(page, "1000 LOAD")
    assert "Error" not in screen
    type_line(page, "Set.Up.Robot")
    wait_for("the servo's words to be found by name",
             lambda: js(page, "window.lab.servo['Desire.Pos']"))
    assert js(page, "window.lab.status.power") == "off"       # booted as make run does
    click(page, "#power")                            # the servo holds the axes: rack on
    wait_for("the amplifiers on", lambda: js(page, "window.lab.status.power") == "on")
    assert page.find_element(By.ID, "power").text == "Amplifiers ON"
    robot_before = js(page, "document.getElementById('robot').toDataURL()")
    start = js(page, "window.lab.latest.map(r => r[5])")
    click(page, '#speeds button[data-speed="real"]')  # the scope's 30 s keep the whole move
    wait_for("real pace", lambda: js(page, "window.lab.status.speed") == "real")
    type_line(page, "800 800 400 0 Abs.Move")
    assert wait_for("Desire.Pos to follow the move",
                    lambda: js(page, "window.lab.servo['Desire.Pos']") == [800, 800, 400, 0])
    arrived = set()                                  # each axis, once it is there (it hunts)

    def near():
        counters = js(page, "window.lab.latest.map(r => r[6])")
        arrived.update(a for a, t in enumerate((800, 800, 400)) if abs(counters[a] - t) < 60)
        return len(arrived) == 3
    wait_for("x, y, z to come near their targets", near)
    end = js(page, "window.lab.latest.map(r => r[5])")
    assert all(abs(e - s - moved) < 150 for s, e, moved in zip(start, end, (800, 800, 400)))
    assert js(page, "document.getElementById('robot').toDataURL()") != robot_before
    click(page, "#pause")
    wait_for("the pause", lambda: js(page, "window.lab.status.state") == "pause")
    click(page, '#windows button[data-window="30"]')
    for axis in (0, 1, 2):                           # the scope's window holds the move
        click(page, f'#axes button[data-axis="{axis}"]')
        counters = js(page, "windowRows().rows.map(r => r[6])")
        assert min(counters) < 50 and max(counters) > 350
    csv = js(page, "window.lab.csv()")
    assert csv.startswith(",".join(COLUMNS) + "\n") and ",Z," in csv   # the gripper's too
    assert parse_rows(csv.splitlines(), "the page's CSV")          # a plant trace, as it says


def test_pause_holds_simulated_time_and_step_is_one_tick(page):
    assert js(page, "window.lab.status.state") == "pause"     # since the move
    held = js(page, "window.lab.status")
    page.execute_script("return new Promise(r => setTimeout(r, 500))")
    assert js(page, "window.lab.status") == held
    click(page, "#step")
    wait_for("one tick", lambda: js(page, "window.lab.status.tick") == held["tick"] + 1)
    stepped = js(page, "window.lab.status")
    assert stepped["state"] == "pause"
    assert abs(stepped["time"] - held["time"] - 1 / 60) < 2e-6
    click(page, '#axes button[data-axis="0"]')       # x's hunting, tick by tick
    click(page, '#windows button[data-window="2"]')
    page.save_screenshot(str(ARTIFACTS / "lab.png"))
    click(page, "#pause")                            # now reads "Run"
    wait_for("the run to go on", lambda: js(page, "window.lab.status.time") > stepped["time"])


def test_the_asn_shows_its_trial_steps_payoff_and_weights(page):
    """Blocks 1070-1078 (docs/learning.md) after the move test's Set.Up.Robot."""
    assert js(page, "document.getElementById('asn').hidden")
    if js(page, "window.lab.status.state") == "pause":
        click(page, "#pause")                        # Run
    click(page, '#speeds button[data-speed="full"]')
    assert "Error" not in type_line(page, "1070 LOAD")
    type_line(page, "1 Trials", timeout=120)
    wait_for("the ASN's words and weights", lambda: js(
        page, "window.lab.servo['Trial.No'] === 1 && (window.lab.servo.Weights || []).length"))
    text = wait_for("the panel to show them", lambda: (lambda t: t.startswith(
        "ASN: trials done 1, steps ") and t)(js(page, "document.getElementById('asn-text')"
                                                ".textContent")))
    assert "payoff" in text and "late moves" in text
    assert not js(page, "document.getElementById('asn').hidden")
    assert any(js(page, "window.lab.servo.Weights"))                 # it learned something
    page.save_screenshot(str(ARTIFACTS / "lab-asn.png"))


def test_bye_in_the_page_leaves_and_flushes(page, lab_server):
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").send_keys("BYE\n")
    assert lab_server.proc.wait(timeout=60) == 0
    assert "FLUSH answered ok" in lab_server.text()
    wait_for("the page to say so", lambda: js(page, "window.lab.ended"))
