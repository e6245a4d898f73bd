"""The server's side of the program pane and the lessons (issue 18, items 4-5): a
block asked for comes back with its lines and the code each laid down; a block
outside the disk, a bad field, an exercise that is not one of the five are
refused with a reason; an exercise's check runs its commands and sends what they
printed; a second click while one runs is refused."""
import asyncio

from harness.commands.lab import block_listing
from harness.lab import lesson_checks
from harness.lab.page_client import Page
from harness.lab.program_pane import ProgramPane, block_lines
from harness.machine.build import PRISTINE_DISK

TIMEOUT = 60


def talk(server, messages, wanted):
    """Send `messages`, collect the answers whose kind is in `wanted` until one of
    each message has its answer (len(messages) answers)."""
    async def run():
        page = await Page.open(server)
        try:
            for message in messages:
                await page.send(message)
            return [await page.until(lambda m: m["t"] in wanted, TIMEOUT) for _ in messages]
        finally:
            await page.close()
    return asyncio.run(run())


def test_a_block_comes_with_its_listing_and_bad_asks_are_refused(lab_server):
    answers = talk(lab_server, [
        {"t": "program", "block": 1008},
        {"t": "program", "block": 10240},
        {"t": "program", "block": "1008"}], {"program", "error"})
    [bad] = [a for a in answers if a["t"] == "error"]        # answered at once
    good, outside = sorted((a for a in answers if a["t"] == "program"), key=lambda a: a["block"])
    assert good["t"] == "program" and good["why"] is None and len(good["lines"]) == 16
    assert good["lines"][2].startswith("CODE Interrupt.Servo") or "Interrupt.Servo" in "".join(
        good["lines"])
    assert any("MOV" in row for rows in good["code"] for row in rows)   # the disassembly
    assert outside["why"] == "no block 10240: the disk has blocks 0..10239"
    assert bad["t"] == "error" and "field 'block' is str, not int" in bad["why"]


def test_an_exercise_check_runs_its_commands_and_a_second_click_is_refused(lab_server):
    refused, again, checked = talk(lab_server, [      # the errors come at once
        {"t": "check", "exercise": 6},
        {"t": "check", "exercise": 2},
        {"t": "check", "exercise": 2}], {"checked", "error"})
    assert refused["t"] == "error" and "not one of 1, 2, 3, 4, 5" in refused["why"]
    assert again == {"t": "error", "why": "exercise 2's check is running already"}
    assert checked["exercise"] == 2 and checked["ok"] is True
    assert checked["text"].count("$ python -m harness tick --ticks 8") == 2
    assert "Velocity" in checked["text"] and "Ramp.Servo" in checked["text"]


def test_block_lines_and_the_cache_follow_the_disk(tmp_path):
    image = tmp_path / "robot.dsk"
    image.write_bytes(PRISTINE_DISK.read_bytes())
    listed = []

    def counted(image, block):
        listed.append(block)
        return block_listing(image, block)
    pane = ProgramPane(image, counted)
    assert pane.message(200)["why"] == "block 200 is blank"
    assert any("Velocity" in row for row in pane.message(1006)["code"][7])   # listing.py's
    assert "Interrupt.Servo" in pane.message(1008)["lines"][1]
    assert any("RTI" in row for rows in pane.message(1008)["code"] for row in rows)
    assert listed == [1006]                  # one listing run for the appendix's blocks
    data = bytearray(image.read_bytes())
    data[200 * 1024:200 * 1024 + 10] = b"( changed "
    image.write_bytes(bytes(data))
    assert block_lines(image, 200)[0].startswith("( changed ")
    changed = pane.message(200)                       # the image changed: read again
    assert changed["lines"][0].startswith("( changed ")
    assert changed["why"] == "no listing: python -m harness listing lists blocks from 1000 on"
    data[1099 * 1024:1099 * 1024 + 10] = b"NoSuchWord"      # a block whose LOAD fails
    image.write_bytes(bytes(data))
    mine = pane.message(1099)["why"]
    assert mine.startswith("no listing:") and "undefined word: NoSuchWord" in mine, mine


def test_a_check_is_shown_as_the_reader_types_it():
    assert lesson_checks.shown(lesson_checks.CHECKS[4][1][0]) == \
        "python -m harness timing --servo idle"
    assert lesson_checks.tail("a\nb\nc", 2) == "...\nb\nc"


SQUARE = [                      # docs/exercises.md's answer to exercise 5, lines 1-5
    "( exercise 5: a square )",
    ": Wait ( n -- )   0 DO  100O 177546O !",
    "   BEGIN 177546O @ 200O AND END  LOOP ;",
    ": Corner ( x y -- )   400 0 Abs.Move  120 Wait ;",
    ": Square ( -- )   1600 0 Corner  1600 1600 Corner",
    "   0 1600 Corner  0 0 Corner ;",
]


def test_exercise_5s_check_runs_the_students_block_from_a_copy_of_the_disk(tmp_path):
    image = tmp_path / "robot.dsk"
    data = bytearray(PRISTINE_DISK.read_bytes())
    block = "".join(line.ljust(64) for line in SQUARE).ljust(1024).encode()
    data[1100 * 1024:1101 * 1024] = block
    image.write_bytes(bytes(data))
    ok, text = asyncio.run(lesson_checks.run_check(5, image))
    assert ok, text
    assert "$ python -m harness run /tmp/ex/square.script --disk /tmp/ex/copy-of-the-lab-disk.dsk" \
        in text and "0 failed" in text
    counters = text.split("the end of /tmp/ex/square.transcript:")[1]
    x, y = (int(n) for n in counters.split("Read.Counter .")[-1].split()[:2])
    assert abs(x) < 100 and abs(y) < 100, counters          # back at the corner 0 0
    assert image.read_bytes() == bytes(data)           # the lab's disk untouched
    blank = tmp_path / "blank.dsk"
    blank.write_bytes(PRISTINE_DISK.read_bytes())
    ok, text = asyncio.run(lesson_checks.run_check(5, blank))
    assert not ok and "undefined word: Square" in text and "exit status 1" in text
