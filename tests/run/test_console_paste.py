"""Pastes into the console (issue 23): every definition arrives and no error, and
^C and ^E act at once while a paste is still waiting. The 5 000- and 30 000-
character pastes, at both paces and into the lab page too, are make fuzz's
(harness/fuzz/paste_runs.py)."""
import shutil

from harness.fuzz.paste_text import check_line, definitions, expected
from tests.lazy import lazy
from tests.run.common import IDLE_SPEED, PRISTINE, ended, harness_console, needs_build

paste_runs = lazy("harness.fuzz.paste_runs")    # aiohttp (its lab half), at the test

pytestmark = needs_build


def test_a_paste_of_1000_characters_arrives_whole(tmp_path):
    # raises when one is missing
    seconds, n = paste_runs.console_paste(1000, True, tmp_path, idle_speed=100)
    assert n == 19


def paste_at_real_pace(tmp_path, chars):
    disk = tmp_path / "paste.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = paste_runs.console(disk, fast=False)
    text, n = definitions(chars)
    child.send(text + check_line() + "\r")
    child.expect(r"definition 3  ok\r\n")                # the paste is under way
    return child, n


def test_ctrl_c_drops_what_a_paste_still_has_waiting_and_says_how_much(tmp_path):
    child, n = paste_at_real_pace(tmp_path, 30000)
    child.send("\x03")
    child.expect(r"\[console\] \^C: (\d+) characters typed or pasted and not yet read by "
                 r"the machine were dropped", timeout=5)
    assert int(child.match.group(1)) > 20000
    # the FORTH names the word it was reading if the ^C lands inside a line
    child.expect(r"Error: interrupted by \^C(?:: [^\r\n]+)?\r\n", timeout=5)
    child.expect(r"(\d+) typed-ahead characters dropped by \^C", timeout=5)
    child.send("2 3 + .\r")
    child.expect(r"5  ok\r\n", timeout=10)                # at once: nothing pasted is left
    child.send("P1000 .\r")
    child.expect("Error: undefined word: P1000")
    child.send("BYE\r")
    assert ended(child, timeout=60) == 0


def test_ctrl_e_during_a_paste_stops_at_sim_and_cont_finishes_it_whole(tmp_path):
    child, n = paste_at_real_pace(tmp_path, 1200)      # ^E finds 900 or more still waiting
    child.send("\x05")
    child.expect("sim> ", timeout=5)
    child.send("show clk\r")
    child.expect("sim> ")
    for line in ("set clk norealtime", "set cpu idle", "set clk idlespeed=100"):
        child.send(line + "\r")           # the rest at full speed: what waits counts, not the pace
        child.expect("sim> ")
    child.send("cont\r")
    child.expect(f"{expected(n)}  ok\r\n", timeout=60)
    assert "Error" not in child.before
    child.send("BYE\r")
    assert ended(child, timeout=60) == 0


def test_keys_typed_while_the_machine_boots_wait_for_its_prompt(tmp_path):
    """SIMH empties the pty as it starts the machine (GO): a line typed before the
    FORTH's first prompt waits in the harness instead of being lost."""
    disk = tmp_path / "boot.dsk"
    shutil.copyfile(PRISTINE, disk)
    child = harness_console("--fast", *IDLE_SPEED, "--disk", disk, encoding="latin-1")
    child.send("2 3 + .\r")
    child.expect(r"blocks 0-\d+\.\r\n ok\r\n")
    child.expect(r"2 3 \+ \. 5  ok\r\n")
    child.send("BYE\r")
    assert ended(child, timeout=60) == 0
