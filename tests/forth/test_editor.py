"""The line editor (vocabulary EDITOR): write and fix blocks at the terminal.

The main test writes a block with the editor, FLUSHes, restarts the emulator on the
same image, lists the block again, loads it, and has gforth list the same image as
a block file."""
import re
import subprocess

import pytest

from harness.machine.machine import Machine, blank_disk

SESSION = [
    ("0 P ( squares and cubes )", "( squares and cubes )"),
    ("1 P : SQUARE ( n -- n*n ) DUP * ;", ": SQUARE ( n -- n*n ) DUP * ;"),
    ("2 P : CUBE ( n -- n^3 ) DUP SQUARE * ;", ": CUBE ( n -- n^3 ) DUP SQUARE * ;"),
    ("3 P   \\ indented comment", "  \\ indented comment"),
]


def listed_lines(text):
    """{line number: text} from the output of LIST (ours or gforth's)."""
    lines = {}
    for row in text.splitlines():
        m = re.match(r"^\s?(\d{1,2}) ?(.*)$", row)
        if m and 0 <= int(m.group(1)) <= 15:
            lines[int(m.group(1))] = m.group(2).rstrip()
    return lines


@pytest.fixture
def image(tmp_path):
    return blank_disk(tmp_path / "rl02.dsk")


def test_edit_flush_reboot_list_load_and_gforth(image):
    expected = {n: text for n, (_, text) in enumerate(SESSION)}
    with Machine(disk=image) as m:
        assert not m.reply("200 WIPE").ok        # editor words live in EDITOR
        m.send("EDITOR 200 WIPE")
        for command, _ in SESSION:
            m.send(command)
        m.send("FLUSH FORTH")
    with Machine(disk=image) as m:               # a fresh boot on the same image
        out = listed_lines(m.send("200 LIST"))
        for n, text in expected.items():
            assert out[n] == text
        assert all(out[n] == "" for n in range(len(SESSION), 16))
        assert m.send("200 LOAD  3 CUBE .  4 SQUARE .").split() == ["27", "16"]
    gforth = subprocess.run(["gforth", "-e", f"use {image} 200 list bye"],
                            capture_output=True, text=True, timeout=30)
    assert gforth.returncode == 0, gforth.stderr
    theirs = listed_lines(gforth.stdout)
    for n, text in expected.items():
        assert theirs[n] == text


def test_insert_delete_erase_spread(image):
    with Machine(disk=image) as m:
        m.send("EDITOR 300 WIPE")
        for n in range(16):
            m.send(f"{n} P line {n}")
        m.send("2 INS new two")                  # 2..14 move down, 15 is lost
        out = listed_lines(m.send("L"))
        assert [out[n] for n in (1, 2, 3, 15)] == ["line 1", "new two", "line 2", "line 14"]
        m.send("0 D")                            # everything moves up, 15 blank
        out = listed_lines(m.send("L"))
        assert [out[n] for n in (0, 1, 2, 14, 15)] == \
            ["line 1", "new two", "line 2", "line 14", ""]
        m.send("1 E")
        assert listed_lines(m.send("1 T")) == {1: ""}
        m.send("0 S")                            # blank line in front
        out = listed_lines(m.send("L"))
        assert [out[n] for n in (0, 1, 2, 3, 15)] == ["", "line 1", "", "line 2", "line 14"]


def test_copy_wipe_and_browse(image):
    with Machine(disk=image) as m:
        m.send("EDITOR 400 WIPE 0 P ( four hundred )")
        m.send("400 401 COPY")
        assert m.send("SCR @ .").split() == ["401"]
        m.send("B")                              # back to 400
        assert m.send("SCR @ .").split() == ["400"]
        assert "( four hundred )" in m.send("N")
        m.send("400 WIPE FLUSH")
    data = image.read_bytes()
    assert data[400 * 1024:401 * 1024] == b" " * 1024
    assert data[401 * 1024:401 * 1024 + 18] == b"( four hundred )  "


def test_bad_editor_input_changes_nothing(image):
    with Machine(disk=image) as m:
        m.send("EDITOR 500 WIPE 0 P keep me")
        r = m.reply("0 P " + "x" * 65)
        assert not r.ok and "longer than 64" in r.error
        # an error while editing keeps the editor selected (issue 18)
        r = m.reply("16 P out of range")
        assert not r.ok and "0..15" in r.error
        assert not m.reply("-1 D").ok
        assert listed_lines(m.send("0 T")) == {0: "keep me"}
        m.send("0 P " + "y" * 64)                # exactly 64 is fine
        assert listed_lines(m.send("0 T")) == {0: "y" * 64}


def test_change_text_inside_a_line(image):
    with Machine(disk=image) as m:
        m.send("EDITOR 600 WIPE 0 P : SQ DUP* ; ( square )")
        m.send("0 C DUP*^DUP *")
        m.send("0 C ( square )^( n -- n*n )")
        assert listed_lines(m.send("0 T")) == {0: ": SQ DUP * ; ( n -- n*n )"}
        m.send("0 C SQ ^")                       # an empty new text deletes
        assert listed_lines(m.send("0 T")) == {0: ": DUP * ; ( n -- n*n )"}
        for bad, message in [("0 C absent^x", "not in the line"),
                             ("0 C no caret", "use: n C old^new"),
                             ("0 C ^x", "use: n C old^new"),
                             ("0 C DUP^" + "D" * 60, "longer than 64")]:
            r = m.reply("EDITOR " + bad)
            assert not r.ok and message in r.error, bad
        assert listed_lines(m.send("EDITOR 0 T")) == {0: ": DUP * ; ( n -- n*n )"}
        assert listed_lines(m.send("L"))[1] == ""


def test_an_editor_word_outside_the_order_says_how_to_select_it(image):
    with Machine(disk=image) as m:
        m.send("EDITOR 200 WIPE 0 P first")
        assert m.reply("NOSUCH").error == "undefined word: NOSUCH"   # the editor stays
        m.send("1 P second")
        m.send("FORTH")                          # the user leaves it
        r = m.reply("1 P second")
        assert r.error == "undefined word: P (a word of EDITOR: type EDITOR to select it again)"
        m.send("EDITOR 1 P second")
        assert m.send("1 T").rstrip() == "\r\n 1 second"


def test_an_error_inside_a_code_word_leaves_the_assembler(image):
    """FORTH-79's CONTEXT := CURRENT after an error is kept where it matters: a
    CODE word cut short does not leave ASSEMBLER as the context."""
    with Machine(disk=image) as m:
        assert not m.reply("CODE HALF R0 R1 MOV, NOSUCH").ok
        assert m.send("CONTEXT @ ' FORTH >BODY = .").strip() == "-1"
