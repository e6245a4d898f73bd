"""The running lab lets the page's terminal reach SIMH's sim> only through the
commands it may run (issue 18): each refused line is answered with one line
saying why and does nothing (the files it would write are not written, the shell
command it would run does not run); the allowed ones, abbreviated as SIMH
abbreviates, run; QUIT from the page leaves the lab through its FLUSH."""
import asyncio
import re

import pytest

from harness.lab.page_client import Page as Client

TIMEOUT = 20


def lab_state(messages):
    """What the lab's frames last said of its status and servo words (for a
    failure: a hint that never came may be a servo table that never filled)."""
    status = next((m["status"] for m in reversed(messages) if m.get("status")), None)
    servo = next((m["servo"] for m in reversed(messages) if m.get("servo") is not None), None)
    return (f"status {status}; servo words {sorted(servo) if servo else servo}, "
            f"Command.Status {servo.get('Command.Status') if servo else None}")


class Page:
    """The page's console as these tests use it: keys sent without waiting for their
    answer, the console read until a pattern shows. harness/lab/page_client.py's
    client does the reading (each message checked against the protocol) and keeps
    the deadline."""

    def __init__(self, client):
        self.client = client

    screen = property(lambda self: self.client.screen)

    async def send(self, message):
        await self.client.send(message)

    async def type(self, text):
        await self.send({"t": "key", "d": text})

    async def message(self, wanted, timeout=TIMEOUT):
        """The first message `wanted` accepts (the console kept on the way)."""
        return await self.client.until(wanted, timeout)

    async def until(self, pattern, start=0):
        """Read until `pattern` shows in the console after `start`; the text."""
        regex = re.compile(pattern)
        if not regex.search(self.screen, start):
            try:
                await self.message(lambda m: regex.search(self.screen, start))
            except AssertionError as why:
                refused = [m["why"] for m in self.client.messages if m["t"] == "error"]
                raise AssertionError(f"no {pattern!r}: {why}; refused: {refused}; "
                                     f"the lab's last {lab_state(self.client.messages)}") from None
        return self.screen[start:]


    async def at_sim(self, line, answer):
        """Type `line` at sim> and wait for `answer` and the next prompt."""
        start = len(self.screen)
        await self.type(line + "\r")
        return await self.until(answer + r"[\s\S]*sim> $", start)


def session(server, steps):
    async def run():
        page = Page(await Client.open(server))
        try:
            await page.until(r"ok\r\n")              # the FORTH is up
            # the page before this one may hold the keyboard still (its close not yet
            # handled): its keys would be refused. One socket's messages go in order.
            await page.send({"t": "take"})
            return await steps(page)
        finally:
            await page.client.close()
    return asyncio.run(run())


async def cont(page):
    """CONT, then empty lines until the FORTH answers one."""
    await page.type("cont\r")
    await answering(page)


async def answering(page):
    """Empty lines until the FORTH answers one: SIMH discards what reaches the
    terminal before the machine runs again (TCSAFLUSH) after CONT."""
    for _ in range(40):
        start = len(page.screen)
        await page.type("\r")
        try:
            await asyncio.wait_for(page.until(r"ok\r\n", start), 0.25)
            return
        except asyncio.TimeoutError:
            pass
    raise AssertionError("the FORTH did not come back after CONT")


async def to_sim(page):
    start = len(page.screen)
    await page.type("\x05")
    await page.until(r"sim> $", start)


REFUSED = [   # line typed at sim>, what the refusal names
    ("! touch {tmp}/shell-ran", "! runs a command in the host's shell"),
    ("attach dz 2323", "ATTACH opens a host file"),
    ("at lpt {tmp}/attached", "ATTACH opens a host file"),
    ("detach rl0", "DETACH would close"),
    ("save {tmp}/saved", "SAVE writes a host file"),
    ("restore {tmp}/saved", "RESTORE reads a host file"),
    ("do {tmp}/script", "DO runs the commands of a host file"),
    ("load {tmp}/x", "LOAD reads a host file"),
    ("dump {tmp}/dumped", "DUMP writes a host file"),
    ("set console log={tmp}/log", "SET CONSOLE: the page may SET only"),
    ("set console telnet=2324", "SET CONSOLE: the page may SET only"),
    ("set log {tmp}/log", "SET LOG: the page may SET only"),
    ("set dz lines=8", "SET DZ: the page may SET only"),
    ("set cpu 16k", "SET CPU 16k: the page may set only HISTORY on CPU"),
    ("set cpu hist=10,nommu", "SET CPU nommu: the page may set only HISTORY"),
    ("set plant disabled", "SET PLANT disabled: the page may set only"),
    ("show @{tmp}/shown plant", "SHOW @FILE writes its output to a host file"),
    ("ex @{tmp}/examined pc", "EXAMINE @FILE writes"),
    ("d rl0 0 1", "DEPOSIT into a disk, tape or line unit"),
    ("break 2000;! touch {tmp}/shell-ran", "BREAK with ;ACTIONS"),
    ("reset", "RESET resets the machine"),
    ("boot rl0", "BOOT reboots the machine"),
    ("frobnicate", "frobnicate is not a SIMH command"),
    ("show " + "x" * 300, "longer than 200 characters"),
]


def test_each_refused_line_says_why_and_does_nothing(lab_server, tmp_path):
    async def steps(page):
        await to_sim(page)
        for line, why in REFUSED:
            line = line.format(tmp=tmp_path)
            text = await page.at_sim(line, r"lab: refused: ")
            assert why in text, (line, text)
            assert "Unknown command" not in text and "Command not allowed" not in text
        # nothing above ran: the files are not there, SIMH never saw the lines
        assert list(tmp_path.iterdir()) == []
        await cont(page)
        start = len(page.screen)
        await page.type("2 3 + .\r")
        return await page.until(r"5  ok", start)
    session(lab_server, steps)


def test_a_refused_line_edited_into_an_allowed_one_runs_as_shown(lab_server, tmp_path):
    """The server edits the sim> line itself: backspace, ^U and ^W act before the
    check, so what SIMH runs is what was checked."""
    async def steps(page):
        await to_sim(page)
        text = await page.at_sim(f"! touch {tmp_path}/x\x15sh lab", r"LAB, ")
        assert "lab: refused" not in text
        text = await page.at_sim(f"show \x17\x17att\x7f\x7f\x7fshow lab", r"LAB, ")
        assert "lab: refused" not in text
        text = await page.at_sim("show lab\x17\x17\x17\x17set console log=x", "refused")
        assert "SET CONSOLE" in text
        await cont(page)
    session(lab_server, steps)
    assert list(tmp_path.iterdir()) == []


def test_allowed_commands_run_abbreviated_as_simh_abbreviates(lab_server):
    async def steps(page):
        await to_sim(page)
        assert "PLANT, " in await page.at_sim("sh plant", r"PLANT, ")
        assert re.search(r"PC:\s+\d+", await page.at_sim("e pc", r"PC:\s+\d+"))
        assert re.search(r"R0:\s+\d+", await page.at_sim("ex r0", r"R0:\s+\d+"))
        await page.at_sim("set cpu hist=100", r"")
        assert "PC " in await page.at_sim("sh cpu history=3", r"PC ")
        await page.at_sim("se plant power=on", r"")
        assert "power=on" in await page.at_sim("sh plant", r"power=\w+")
        await page.at_sim("set plant pow=off", r"")
        start = len(page.screen)
        await page.type("s\r")                    # STEP: one instruction, back at sim>
        assert "Step expired" in await page.until(r"sim> $", start)
        await cont(page)
        start = len(page.screen)
        await page.type("1 2 + .\r")
        await page.until(r"3  ok", start)
    session(lab_server, steps)


def test_keys_typed_right_after_ctrl_e_wait_for_the_prompt(lab_server):
    """^E and a command in one message: the command waits for sim> (it is not
    typed to the FORTH, nor lost when SIMH discards pending input at its prompt)."""
    async def steps(page):
        start = len(page.screen)
        await page.type("\x05show lab\r")
        text = await page.until(r"LAB, [\s\S]*sim> $", start)
        await cont(page)
        return text
    assert "LAB, " in session(lab_server, steps)


def test_arrow_keys_do_not_reach_the_forth_line(lab_server):
    async def steps(page):
        start = len(page.screen)
        await page.type("1 \x1b[A\x1b[D2\x1bOC + .\r")
        # this line's answer: an earlier test's CONT may leave empty lines' "ok"s to come
        return await page.until(r"\+ \.[^\n]*(ok|Error[^\n]*)\r\n", start)
    text = session(lab_server, steps)
    assert "3  ok" in text and "[A" not in text


def test_quit_from_the_page_leaves_through_flush(tmp_path_factory):
    """QUIT at the page's sim> reaches SIMH, which FLUSHes the FORTH's blocks
    first (leave_check.c); the lab reports it and ends."""
    from harness.lab.launch import LabProcess
    server = LabProcess(tmp_path_factory.mktemp("quit"))

    async def steps(page):
        await to_sim(page)
        await page.type("qu\r")
        return await page.until(r"FLUSHed the FORTH's UPDATEd blocks first")
    try:
        text = session(server, steps)
        status = server.proc.wait(timeout=60)          # QUIT ends the lab by itself
    finally:
        server.stop()
    assert "left at sim>" in text and status == 0


@pytest.mark.parametrize("line", ["show version"])
def test_simh_never_ends_a_line_on_cr_at_its_prompt(line, tmp_path):
    """The lab's terminal settings (prompt_termios): at sim>, keys meant for the
    FORTH (CR-ended) that reach SIMH never complete a command; the guard's LF does,
    and its two ^U first erase what came unchecked."""
    import pexpect

    from harness.lab.sim_prompt_guard import KILL, prompt_termios
    from harness.machine import pty_child
    from harness.machine.build import BUILD
    child = pexpect.spawn(str(BUILD / "pdp11"), timeout=10, preexec_fn=prompt_termios)
    try:
        child.expect(b"sim> ")
        child.send(f"! touch {tmp_path}/ran\r".encode())
        child.send(b"\x03\x1c\x1a\x04\x16")       # ^C ^\ ^Z ^D ^V: no signal, no end of line
        child.send(KILL + line.encode() + b"\n")
        child.expect(b"PDP-11 simulator")       # SIMH reads in order: a line ended before
        assert b"sim> " not in child.before     # this one would have had its prompt here
        child.expect(b"sim> ")
        assert not (tmp_path / "ran").exists()
        child.send(b"quit\n")
        child.expect(pexpect.EOF)
    finally:
        pty_child.close(child)


def test_a_move_waiting_on_the_rack_off_gets_a_hint(lab_server):
    """The lab boots with the amplifier rack off; Move.Complete? then waits for
    ever: the console says why after two simulated seconds (harness/lab/rack_hint.py)."""
    async def steps(page):
        for line in ("1000 LOAD", "Set.Up.Robot"):
            start = len(page.screen)
            await page.type(line + "\r")
            await page.until(r"ok\r\n", start)
        start = len(page.screen)
        await page.type("800 0 0 0 Abs.Move Move.Complete?\r")
        text = await page.until(r"rack is OFF[^\n]*\n", start)
        await page.type("\x03")                      # ^C stops the wait
        await page.until(r"interrupted", start)
        return text
    assert "Move.Complete? waits for ever" in session(lab_server, steps)


def test_the_11_23s_clock_needs_the_simulator_that_prices(lab_server):
    """A lab on build/pdp11 (SIMH's own CPU, mk/devices.mk) keeps the count: the page's
    clock button is answered with where the 11/23's clock is (--timed), and SET CLK
    TIMED at its sim> says the same of the simulator; the time base stays the count."""
    async def steps(page):
        hello = next(m for m in page.client.messages if m["t"] == "hello")
        assert hello["status"]["clock"] == "count" and hello["status"]["timable"] is False
        await page.send({"t": "clock", "v": "timed"})
        refused = await page.message(lambda m: m["t"] == "error")
        await to_sim(page)
        said = await page.at_sim("set clk timed", r"TIMED needs[^\r]*")
        assert "rate=300000 instructions/s" in await page.at_sim("show clk", r"CLK, [^\r]*")
        await cont(page)
        return refused["why"], said
    why, said = session(lab_server, steps)
    assert "--timed" in why and "make lab TIMED=1" in why
    assert "build/pdp11-timed" in said
