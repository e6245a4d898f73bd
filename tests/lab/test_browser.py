"""The lab page in Debian's headless Chromium (Selenium with chromium-driver), as a
user would drive it: the terminal answers, the blocks load, a move shows in the
robot drawing and on the scope, pause holds simulated time, step is one tick,
BYE leaves. The screenshot is kept in build/test-artifacts/lab.png."""
import pytest
from selenium.webdriver.common.by import By

from harness.analysis.trace import parse_rows

from labpage import ARTIFACTS, AnotherPage, assert_on_screen, click, connected, frames, \
    full_session, js, pace, pause, projector, run, serious_violations, terminal_spills, type_line, \
    until, wait_for

# The lab boots with the amplifier rack off, as make run does: nothing drifts until
# the page's switch is turned on after Set.Up.Robot. x10 keeps the run short.
LAB_SPEED = "x10"


@pytest.fixture(scope="module")
def page(lab_server, browser):
    browser.get(lab_server.url)
    connected(browser)
    yield browser
    browser.get("about:blank")      # the session's browser waits for other modules: blank,
                                    # not an ended page that still ticks its timers


def test_the_terminal_answers(page):
    assert "2 3 + . 5  ok" in type_line(page, "2 3 + .")
    assert "token=" not in page.current_url          # off the address bar
    violations = serious_violations(page)            # before 1000 LOAD: no servo data yet
    assert not violations, violations
    assert breakpoint_row_in_the_panel(page)          # under the servo table's first note
    clock = page.find_element(By.ID, "clock")          # build/pdp11: the count, and why
    assert clock.text == "by count" and not clock.is_enabled()
    assert "--timed" in clock.get_dom_attribute("title")
    assert page.find_element(By.ID, "simtick").text.endswith("\u00b7 by count")


def test_a_move_shows_on_the_robot_and_the_scope(page, lab_server):
    screen = type_line(page, "1000 LOAD")
    assert "Error" not in screen
    type_line(page, "Set.Up.Robot")
    # once failed after 30 s on a host running at half its speed (make test-browser
    # 188 s, not 80-100): what the page and the lab had then, should it come again
    until(page, "the servo's words to be found by name", "window.lab.servo['Desire.Pos']",
          seen=lambda: f"the page's servo {js(page, 'JSON.stringify(window.lab.servo)')}, "
                       f"status {js(page, 'JSON.stringify(window.lab.status)')}; "
                       f"the lab's log ends {lab_server.text()[-600:]!r}")
    assert js(page, "window.lab.status.power") == "off"       # booted as make run does
    click(page, "#power")                            # the servo holds the axes: rack on
    until(page, "the amplifiers on", "window.lab.status.power === 'on'")
    robot_before, start = js(page, "[document.getElementById('robot').toDataURL(), "
                                   "window.lab.latest.map(r => r[5])]")
    pace(page, "real")                               # the scope's 30 s keep the whole move
    type_line(page, "800 800 400 0 Abs.Move")
    until(page, "Desire.Pos to follow the move",
          "String(window.lab.servo['Desire.Pos']) === '800,800,400,0'")
    until(page, "x, y, z to come near their targets",      # each axis, once it is there
          "[800, 800, 400].map((t, a) => arrived[a] ||= "     # (it hunts)
          "Math.abs(window.lab.latest[a][6] - t) < 60).every(Boolean)",
          setup="const arrived = [];")
    pause(page)                                      # all the rest looks at what is held
    power = page.find_element(By.ID, "power")     # labelled with what a click does
    wait_for("the switch relabelled (at the page's next frame)",
             lambda: power.text == "Turn amps off")
    assert power.get_dom_attribute("aria-pressed") == "true"
    end = js(page, "window.lab.latest.map(r => r[5])")
    assert all(abs(e - s - moved) < 150 for s, e, moved in zip(start, end, (800, 800, 400)))
    assert js(page, "document.getElementById('robot').toDataURL()") != robot_before
    view = js(page, "window.lab.robotView")           # the robot panel: the move's trail,
    assert view["trail"] > 100 and view["origin"] is not None     # the zero it counts from,
    assert view["targets"][-1]["d"] == [800, 800, 400, 0]         # the target, the fingers
    assert view["fingers"] == {"opening": 2.0, "held": False}
    origin = view["origin"]                           # Set.Up.Robot's zero: position - counter
    x = js(page, "window.lab.latest[0]")
    assert abs(origin[0] - (x[5] - x[6])) < 1.5     # the counter is the position, whole
    scope = scope_after_the_move(page)
    assert scope["steps"] == [[0, 800]]               # Desire.Pos: one step, at the move
    assert scope["step_at"] > scope["start"]          # inside the window, with history before it
    assert min(scope["counter"]) < 50 and max(scope["counter"]) > 700   # X's counter moved
    low, high = js(page, "[window.lab.scope.plot.scales.counts.min, window.lab.scope.plot.scales.counts.max]")
    assert low <= min(scope["counter"]) and max(scope["counter"]) <= high   # all of it in sight
    # CH4, the DAC code (a scale without an axis), in its lane: the top quarter, not
    # a full-height band over the counter
    lane = js(page, """(() => { const u = window.lab.scope.plot, s = u.scales['plant:dac'];
      const dac = u.data[4].filter((v) => v !== null);
      return [Math.min(...dac), Math.max(...dac)].map((v) => (v - s.min) / (s.max - s.min)); })()""")
    assert lane[0] < lane[1] and 0.75 <= lane[0] and lane[1] <= 1, lane
    counts = js(page, """(() => { const u = window.lab.scope.plot, s = u.scales.counts;
      const counter = u.data[1].filter((v) => v !== null);
      return [Math.min(...counter), Math.max(...counter)].map((v) => (v - s.min) / (s.max - s.min)); })()""")
    assert 0 <= counts[0] and counts[1] <= 0.75, counts      # and the counter below it


def breakpoint_row_in_the_panel(page):
    """The breakpoint row's bottom is inside the servo panel's (not below its fold)."""
    row, servo = js(page, "['break-row', 'servo-panel'].map("
                          "(e) => document.getElementById(e).getBoundingClientRect().bottom)")
    assert row <= servo, f"the breakpoint row ends at {row}, below the servo panel's fold at {servo}"
    return True


def scope_after_the_move(page):
    """The scope's uPlot data after the move, 30 s window: CH1 X counter, CH2 X Desire.Pos."""
    page.execute_script("document.getElementById('scope-window').value = '30';"
                        "document.getElementById('scope-window').dispatchEvent(new Event('change'))")
    click(page, "#freeze")
    until(page, "the frozen window", "window.lab.scope.view[1] === window.lab.scope.frozen.end")
    return js(page, """(() => {
      const s = window.lab.scope, d = s.plot.data, steps = [];
      let at = null;
      for (let i = 1; i < d[0].length; i++)
        if (d[2][i] !== null && d[2][i - 1] !== null && d[2][i] !== d[2][i - 1]) {
          steps.push([d[2][i - 1], d[2][i]]); at = d[0][i]; }
      return { steps, step_at: at, start: d[0][0], counter: d[1].filter(v => v !== null) };
    })()""")


@full_session
def test_the_scope_cursors_csv_and_overlay(page, tmp_path):
    """Frozen since the move: two cursors read the move's Δt and Δcounts; the CSV is the
    window's samples; a saved run's trace file is overlaid, dashed."""
    view = js(page, "window.lab.scope.view")
    data = js(page, "window.lab.scope.plot.data")
    at = next(t for t, a, b in zip(data[0][1:], data[2], data[2][1:]) if a is not None and a != b)
    page.execute_script(f"window.lab.scope.setCursors({at - 0.5}, {at + 3})")
    wait_for("the readout", lambda: "Δt 3.5000 s" in
             page.find_element(By.ID, "scope-readout").text)
    readout = page.find_element(By.ID, "scope-readout").text
    assert "CH2 0 → 800 (Δ 800)" in readout, readout      # Desire.Pos's step
    moved = int(readout.split("CH1 ")[1].split("(Δ ")[1].split(")")[0])
    assert 700 < moved < 900, readout                               # the counter followed
    assert js(page, "window.lab.scope.view") == view                # Freeze held it
    csv = js(page, "window.lab.scope.csv()").splitlines()
    assert csv[0] == "time_s,X counter,X Desire.Pos,X vel,X dac"
    rows = [line.split(",") for line in csv[1:]]
    # the CSV's times have 9 decimals: a sample at the window's very edge may print
    # half a nanosecond outside it
    assert view[0] - 1e-9 <= float(rows[0][0]) and float(rows[-1][0]) <= view[1] + 1e-9
    held = [r[2] for r in rows]                                     # the step, held (empty
    assert set(held) - {""} == {"0", "800"} and held[-1] == "800"   # before 1000 LOAD)
    # a saved run: this page's own move, as the plant trace python -m harness run writes
    trace = tmp_path / "saved.trace.csv"
    trace.write_text(js(page, """(() => {
      const cols = Object.keys(ROW), rows = [].concat(...window.lab.traces)
        .sort((a, b) => a[0] - b[0] || a[1] - b[1]);
      return cols.join(',') + '\\n' + rows.map(r => cols.map(c => c === 'axis' ? AXES[r[ROW.axis]]
        : r[ROW[c]]).join(',')).join('\\n') + '\\n'; })()"""))
    assert parse_rows(trace.read_text().splitlines(), "the page's rows")   # a plant trace
    for field, value in (("scope-trigger", "rise"), ("scope-level", "400")):   # both runs
        page.execute_script(f"const f = document.getElementById('{field}'); f.value = '{value}';"
                            "f.dispatchEvent(new Event('change'))")         # aligned at 400
    page.find_element(By.ID, "scope-overlay").send_keys(str(trace))
    wait_for("the overlay", lambda: js(page, "window.lab.scope.overlay && window.lab.scope.plot.data.length") == 8)
    saved = js(page, "window.lab.scope.plot.data[5].filter(v => v !== null)")   # saved X counter
    assert min(saved) < 50 and max(saved) > 700
    assert "dashed: saved.trace.csv" in page.find_element(By.ID, "scope-note").text
    page.execute_script("return new Promise(r => setTimeout(r, 300))")
    low, high = js(page, "[window.lab.scope.plot.scales.counts.min, window.lab.scope.plot.scales.counts.max]")
    shown = [v for v in js(page, "window.lab.scope.plot.data[1]") + saved if v is not None]
    assert low <= min(shown) and max(shown) <= high                 # in sight, live and saved
    assert js(page, "window.lab.scope.decimated")                   # 30 s: more rows than pixels,
    assert "min/max of" in page.find_element(By.ID, "scope-note").text   # and it says so
    page.execute_script("window.lab.scope.plot.setSelect({left: 100, width: 200, top: 0, height: 10})")
    zoom = wait_for("the zoom", lambda: js(page, "window.lab.scope.view") != view
                    and js(page, "window.lab.scope.view"))
    assert view[0] < zoom[0] < zoom[1] < view[1] and zoom[1] - zoom[0] < 15   # the dragged span
    click(page, "#pan-back")                                        # half a span back
    wait_for("the pan", lambda: js(page, "window.lab.scope.view") != zoom)
    back = js(page, "window.lab.scope.view")
    assert abs((zoom[0] - back[0]) - (zoom[1] - zoom[0]) / 2) < 1e-6
    click(page, "#freeze")                                          # live again
    assert js(page, "window.lab.scope.frozen") is None


@full_session
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
    page.execute_script("document.getElementById('scope-window').value = '2';"   # x hunting,
                        "document.getElementById('scope-window').dispatchEvent(new Event('change'))")
    page.save_screenshot(str(ARTIFACTS / "lab.png"))
    textarea = page.find_element(By.CSS_SELECTOR, "#terminal textarea")
    textarea.send_keys("1 1 + .")                    # typed while paused: shown, waiting
    shown = wait_for("the typed-ahead line", lambda: page.find_element(By.ID, "typed-ahead"))
    assert shown.is_displayed() and "1 1 + ." in shown.text
    frames(page)                                     # the terminal is refitted above it
    assert not terminal_spills(page), terminal_spills(page)
    click(page, "#pause")                            # now reads "Run"
    wait_for("the run to go on", lambda: js(page, "window.lab.status.time") > stepped["time"])
    wait_for("the typed-ahead line to go",
             lambda: not page.find_element(By.ID, "typed-ahead").is_displayed())
    assert "1 1 + . 2  ok" in type_line(page, "")




@pytest.mark.parametrize("width, height", [(1280, 720), (1920, 1080)])
def test_the_page_fits_both_projectors_without_scrolling(page, width, height):
    """Each panel present, nothing scrolls, at both projector sizes; the screenshots
    (build/test-artifacts/lab-WIDTH.png) are looked at by eye."""
    if width == 1280:                                # a longer move, for the trail to show
        pace(page, "x10")                            # the move test chose real pace; chosen
        run(page)                                    # while it is paused (the move test's),
        type_line(page, "3200 -2400 400 0 Abs.Move")   # the lab runs only for the move
        until(page, "the move", "window.lab.latest[0][6] > 3000")
        pause(page)                                  # its trail (the last 10 simulated
        # seconds) stays in the screenshots; and paused, no data comes, so the page
        # draws only when the layout changes: running, Chromium drew ~27 frames a
        # second through both sizes' checks, some 3 CPU-s of make test's
        pace(page, "real")                           # as the later tests had it
    with projector(page, width, height):
        assert_on_screen(page, width, height,
                         ("console-panel", "robot-panel", "servo-panel", "scope-panel"))
        front = page.find_element(By.ID, "front-panel").text    # the 11/23, live
        assert "PSW" in front and "IP" in front and "DAC X" in front
        assert js(page, "window.lab.panel.registers.length") == 8
        box = js(page, "document.getElementById('front-panel').getBoundingClientRect().toJSON()")
        assert box["bottom"] <= height, "the front panel is cut off"
        assert breakpoint_row_in_the_panel(page)
        low, high = js(page, "[window.lab.scope.plot.scales.counts.min, window.lab.scope.plot.scales.counts.max]")
        shown = [v for v in js(page, "window.lab.scope.plot.data[1]") if v is not None]
        assert low <= min(shown) and max(shown) <= high     # the scope's counts all in sight
        page.save_screenshot(str(ARTIFACTS / f"lab-{width}.png"))
        violations = serious_violations(page)
        assert not violations, violations
        held = js(page, "window.lab.keyboard")        # another page's note, as its message
        page.execute_script("takeKeyboard({holder: 'page 9', you: false})")   # would show it
        try:                                         # (test_the_keyboard_note_...: a real one)
            frames(page)
            assert not terminal_spills(page), terminal_spills(page)
            assert not heading_wrapped(page), heading_wrapped(page)
        finally:
            page.execute_script("takeKeyboard(arguments[0])", held)


@full_session
def test_the_keyboard_note_leaves_the_terminal_in_its_panel(page, lab_server):
    """Another page takes the keyboard while the window keeps its size: the note and its
    button come into the console's heading, on its one line, and the terminal is fitted
    again below it (not only at a window's resize), over no other panel, nothing
    scrolling. Screenshots build/test-artifacts/lab-keyboard-WIDTH.png."""
    for width, height in ((1920, 1080), (1280, 720)):
        page.execute_script("window.lab.take()")
        wait_for("this page to hold the keyboard", lambda: js(page, "window.lab.keyboard.you"))
        with projector(page, width, height):         # fitted with "You hold the keyboard"
            frames(page)
            other = AnotherPage(lab_server)
            try:
                wait_for("the note", lambda: page.find_element(By.ID, "take").is_displayed())
                frames(page)
                assert not terminal_spills(page), (width, terminal_spills(page))
                assert not heading_wrapped(page), (width, heading_wrapped(page))
                page.save_screenshot(str(ARTIFACTS / f"lab-keyboard-{width}.png"))
                if width == 1280:                    # the button as the smaller size has it
                    violations = serious_violations(page)
                    assert not violations, violations
            finally:
                other.close()
    page.execute_script("window.lab.take()")
    wait_for("this page to hold the keyboard again", lambda: js(page, "window.lab.keyboard.you"))


def heading_wrapped(page):
    """The console heading's parts shown below its title's line (the heading wrapped)."""
    return js(page, """(() => {
      const h2 = document.querySelector('#console-panel h2'), title = document.createRange();
      title.selectNodeContents(h2.firstChild);      // "Console"
      const bottom = title.getBoundingClientRect().bottom;
      return [...h2.children].filter((e) => e.getClientRects().length
        && e.getBoundingClientRect().top >= bottom).map((e) => e.id || e.tagName); })()""")


def test_the_badge_says_when_simh_has_the_machine_stopped(page):
    run(page)                                        # the projector test paused it
    textarea = page.find_element(By.CSS_SELECTOR, "#terminal textarea")
    textarea.send_keys("\x05")
    wait_for("the badge", lambda: page.find_element(By.ID, "state").text == "STOPPED sim>")
    screen = type_line(page, "attach lpt /tmp/x", answer="lab: refused")
    assert "ATTACH opens a host file" in screen
    textarea.send_keys("cont\n")
    wait_for("the badge", lambda: page.find_element(By.ID, "state").text.startswith("RUN"))


@full_session
def test_a_breakpoint_on_a_word_stops_the_machine_and_shows_the_history(page):
    field = page.find_element(By.ID, "break-word")
    field.send_keys(".")                             # the word that prints a number
    click(page, '#break-form button[type="submit"]')
    wait_for("the run again", lambda: page.find_element(By.ID, "state").text.startswith("RUN"))
    page.execute_script("return new Promise(r => setTimeout(r, 500))")   # CONT's input flush
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").send_keys("5 .\n")
    shown = wait_for("the history", lambda: page.find_element(By.ID, "history").is_displayed())
    wait_for("the badge (drawn at the page's next frame)",
             lambda: page.find_element(By.ID, "state").text == "STOPPED sim>")
    text = page.find_element(By.ID, "history-text").text
    assert "in word" in text and len(text.splitlines()) > 5
    assert all(row[3] for row in js(page, "window.lab.history"))
    page.save_screenshot(str(ARTIFACTS / "lab-breakpoint.png"))
    click(page, "#history-close")
    before = js(page, "window.lab.screen()").count("5  ok")
    click(page, "#nobreak")                          # cleared: the line's answer comes
    wait_for("5  ok", lambda: js(page, "window.lab.screen()").count("5  ok") > before)
    page.find_element(By.CSS_SELECTOR, "#terminal textarea").click()


@full_session
def test_an_io_breakpoint_shows_the_history_and_the_line_and_steps_one_instruction(page):
    """The servo's write of DAC X (SET LAB IOBREAK=170440, io_break.c) stops the
    machine: the history before it, and the program pane on block 1008's line 1, where
    Interrupt.Servo is defined; Step 1 instruction moves the PC; Clear goes on."""
    run(page)
    page.find_element(By.ID, "iobreak-address").send_keys("170440")
    click(page, '#iobreak-form button[type="submit"]')
    wait_for("the history", lambda: page.find_element(By.ID, "history").is_displayed())
    what = page.find_element(By.ID, "history-what").text
    assert "I/O break: write" in what and "170440 (AAV11-A DAC X)" in what, what
    wait_for("the badge", lambda: page.find_element(By.ID, "state").text == "STOPPED sim>")
    wait_for("block 1008's line 1 marked", lambda: js(page, "window.lab.program.block") == 1008
             and page.find_elements(By.CSS_SELECTOR, '#program-text .pl.current[data-line="1"]'))
    assert "stopped in Interrupt.Servo: defined in block 1008, line 1" in \
        page.find_element(By.ID, "program-where").text
    marked = page.find_elements(By.CSS_SELECTOR, "#program-text .pl-code.pc")   # its PC's row
    assert len(marked) == 1 and "170440" in marked[0].text, [m.text for m in marked]
    for width, height in ((1280, 720), (1920, 1080)):
        with projector(page, width, height):
            assert_on_screen(page, width, height, ("console-panel", "program-panel",
                                                   "servo-panel", "scope-panel"))
            page.save_screenshot(str(ARTIFACTS / f"lab-iobreak-{width}.png"))
    click(page, "#history-close")
    pcs = [js(page, "window.lab.panel.registers[7].value")]
    for _ in range(3):
        click(page, "#stepi")
        pcs.append(wait_for("the next PC", lambda: (lambda pc: pc not in pcs and pc)(
            js(page, "window.lab.panel.registers[7].value"))))
    assert "Step expired" in js(page, "window.lab.screen()")
    page.save_screenshot(str(ARTIFACTS / "lab-stepped.png"))
    click(page, "#nobreak")
    wait_for("the run again", lambda: page.find_element(By.ID, "state").text.startswith("RUN"))
    assert js(page, "window.lab.stoppedIn") is None or not js(page, "window.lab.status.prompt")
    click(page, '#views button[data-view="robot-panel"]')


@full_session
def test_the_asn_shows_its_trial_steps_payoff_and_weights(page):
    """Blocks 1070-1078 (docs/learning.md) after the move test's Set.Up.Robot."""
    assert js(page, "document.getElementById('asn').hidden")
    run(page)
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
