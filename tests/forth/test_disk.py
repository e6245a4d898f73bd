"""Blocks on the RL02: driver, LRU buffers, LOAD / --> / ;S / THRU, errors.

Each test works on its own fresh RL02-size image in a temporary directory; block n
is bytes 1024n..1024n+1023 of it, so tests prepare source blocks and check written
blocks by reading the image file directly."""
import hashlib

import pytest

from harness.machine.machine import Machine, blank_disk

BLOCK = 1024


def put_block(image, n, lines):
    """Write block n of the image: up to 16 lines of text, each padded to 64."""
    assert len(lines) <= 16
    text = "".join(line.ljust(64)[:64] for line in lines).ljust(BLOCK)
    with open(image, "r+b") as f:
        f.seek(BLOCK * n)
        f.write(text.encode("ascii"))


def get_block(image, n):
    with open(image, "rb") as f:
        f.seek(BLOCK * n)
        return f.read(BLOCK)


def digest(image):
    return hashlib.sha256(image.read_bytes()).hexdigest()


@pytest.fixture
def image(tmp_path):
    return blank_disk(tmp_path / "rl02.dsk")


@pytest.fixture
def boot(image):
    """A machine booted on the fresh image (the image is prepared first)."""
    machines = []

    def boot(**kw):
        m = Machine(disk=image, **kw)
        machines.append(m)
        return m
    yield boot
    for m in machines:
        m.close()


def test_load_defines_words_and_arrow_continues(image, boot):
    put_block(image, 30, ["( squares )", ": SQ ( n -- n*n ) DUP * ;", "-->"])
    put_block(image, 31, ["( cubes )", ": CUBE ( n -- n^3 ) DUP SQ * ;"])
    put_block(image, 32, ["( nested )", "30 LOAD", ": TWICE-CUBE ( n -- m ) CUBE 2* ;"])
    m = boot()
    # the rest of the terminal line runs after the LOAD: the input is restored
    assert m.send("32 LOAD  3 TWICE-CUBE .  7 SQ .").split() == ["54", "49"]
    assert m.send("BLK @ .").split() == ["0"]


def test_thru_and_semicolon_s(image, boot):
    put_block(image, 40, [": W40 40 ;", ": EARLY ( -- 1 ) 1 ;S 2 ;", ";S", ": NEVER 1 ;"])
    put_block(image, 41, [": W41 41 ;  \\ a comment to the end of the line", ": W41B 410 ;"])
    m = boot()
    assert m.send("40 41 THRU  W40 . W41 . W41B .").split() == ["40", "41", "410"]
    r = m.reply("NEVER")
    assert not r.ok and "undefined word" in r.error
    assert m.send("EARLY DEPTH . .").split() == ["1", "1"]  # compiled ;S is EXIT


def test_error_in_loaded_block_names_block_and_line(image, boot):
    put_block(image, 50, ["( error test )", ": BEFORE ( -- n ) 42 ;", "",
                          "  1 2 NO-SUCH-WORD 3", ": AFTER ( -- n ) 43 ;"])
    put_block(image, 51, ["( loads 50 )", ": OUTER 1 ;", "50 LOAD"])
    m = boot()
    r = m.reply("51 LOAD")
    assert not r.ok
    assert "undefined word" in r.error and "NO-SUCH-WORD" in r.error
    assert "in block 50 line 3" in r.error
    # dictionary intact: words defined before the error stay, the rest never came
    assert m.send("BEFORE . OUTER .").split() == ["42", "1"]
    assert not m.reply("AFTER").ok
    # back at the terminal with an empty stack and BLK = 0
    assert m.send("DEPTH . BLK @ .").split() == ["0", "0"]


def test_error_inside_a_definition_across_lines(image, boot):
    put_block(image, 52, [": HALF ( n -- n/2 )", "  2 /", "  OOPS ;"])
    m = boot()
    r = m.reply("52 LOAD")
    assert not r.ok and "in block 52 line 2" in r.error
    assert not m.reply("HALF").ok          # the half-built word is gone
    assert m.send("5 3 + .").split() == ["8"]


def test_block_past_the_end_is_an_error_and_writes_nothing(image, boot):
    before = digest(image)
    m = boot()
    for line in ["10240 BLOCK", "10240 BUFFER", "-1 BLOCK", "10240 LOAD",
                 "10240 LIST", "0 LOAD"]:
        r = m.reply(line)
        assert not r.ok, line
    r = m.reply("10240 BUFFER")
    assert "no such block" in r.error and "past the end" in r.output
    r = m.reply("EMPTY-BUFFERS UPDATE")
    assert not r.ok and "no current block" in r.error
    # the last block exists, and nothing was ever written
    assert m.send("10239 BLOCK DROP  FLUSH  #WRITES @ .").split() == ["0"]
    m.close()
    assert digest(image) == before


def test_lru_keeps_recent_blocks_and_updated_data(image, boot):
    for n in range(1, 6):
        put_block(image, n, [f"block {n}"])
    m = boot()
    m.send("EMPTY-BUFFERS 0 #READS !")
    # 1 2 3 4 fill the four buffers; touching 1 makes 2 the least recent
    m.send("1 BLOCK DROP 2 BLOCK DROP 3 BLOCK DROP 4 BLOCK DROP 1 BLOCK DROP")
    assert m.send("#READS @ .").split() == ["4"]
    m.send("5 BLOCK DROP 1 BLOCK DROP 3 BLOCK DROP 4 BLOCK DROP")  # 2 went, not 1
    assert m.send("#READS @ .").split() == ["5"]
    m.send("2 BLOCK DROP")
    assert m.send("#READS @ .").split() == ["6"]
    assert m.send("2 BLOCK 7 TYPE").strip() == "block 2"
    # ten UPDATEd blocks through four buffers: six are written back on the way
    m.send("0 #WRITES !")
    m.send(": MARK ( -- ) 110 100 DO I BLOCK 1024 I 35 + FILL UPDATE LOOP ;  MARK")
    assert m.send("#WRITES @ .").split() == ["6"]
    m.send("FLUSH")
    assert m.send("#WRITES @ .").split() == ["10"]
    assert m.send("EMPTY-BUFFERS 105 BLOCK C@ .").split() == ["140"]
    assert m.send("3 BLOCK 7 TYPE").strip() == "block 3"   # a seek inwards
    m.close()
    for n in range(100, 110):
        assert get_block(image, n) == bytes([n + 35]) * BLOCK
    assert get_block(image, 110) == bytes(BLOCK)   # a neighbour is untouched


def test_updated_block_survives_an_error(image, boot):
    m = boot()
    m.send("7 BLOCK 5 CHAR Q FILL UPDATE")
    assert not m.reply("10240 BLOCK").ok
    assert not m.reply("UNDEFINED-THING").ok
    m.send("SAVE-BUFFERS")
    m.close()
    assert get_block(image, 7)[:6] == b"QQQQQ\0"


def test_list_and_index(image, boot):
    put_block(image, 60, ["( title sixty )", "second line"])
    put_block(image, 61, ["( title sixty-one )"])
    m = boot()
    out = m.send("60 LIST").splitlines()
    assert " 0 ( title sixty )" in out and " 1 second line" in out
    assert m.send("SCR @ .").split() == ["60"]
    out = m.send("60 61 INDEX")
    assert "   60 ( title sixty )" in out and "   61 ( title sixty-one )" in out


def test_disk_not_attached_is_a_clear_error(tmp_path):
    with Machine(disk=blank_disk(tmp_path / "x.dsk"),
                 extra_commands="detach rl0\n") as m:
        assert "drive not ready (no disk attached?)" in m.send(".DISK")
        r = m.reply("1 BLOCK")
        assert not r.ok and "block read error" in r.error
        assert "RL0 block 1 read not ready" in r.output and "not-ready" in r.output
        assert m.send("1 2 + .").split() == ["3"]


def test_write_locked_disk_keeps_the_update(tmp_path):
    disk = blank_disk(tmp_path / "ro.dsk")
    with Machine(disk=disk, extra_commands="set rl0 locked\n") as m:
        assert m.send(".DISK").endswith("blocks 0-10239, write-locked.")
        m.send("9 BLOCK 3 CHAR Z FILL UPDATE")
        r = m.reply("FLUSH")
        assert not r.ok and "block write error" in r.error
        assert "write-locked" in r.output
        # the changed buffer is still there, still marked for writing
        assert m.send("9 BLOCK 3 TYPE").strip() == "ZZZ"
    assert get_block(disk, 9) == bytes(BLOCK)


def test_controller_error_names_block_and_status(image, boot):
    # A read of block 5000's sectors while the heads sit on cylinder 0: the
    # RLV12 finds no matching header. The driver's own error path reports it.
    m = boot()
    m.send("EMPTY-BUFFERS 1 BLOCK DROP  5000 RL-BLK ! 6 RL-FN !")
    r = m.reply("5000 RL-DA RLDA ! BUFFERS RLBA ! -512 RLMP ! 6 RL-DO ?RL-OK")
    assert not r.ok and r.error.startswith("block read error")
    assert "RL0 block 5000 read failed: CSR=" in r.output
    assert "header-not-found" in r.output and "drive=" in r.output
    assert m.send("5000 BLOCK DROP 2 2 + .").split() == ["4"]  # the driver recovers


def test_seek_selects_cylinder_and_head(image, boot):
    # After a transfer, READ HEADER reports the track under the heads
    # (cylinder * 2 + head): block n lives on track n / 10.
    m = boot()
    assert m.send(".DISK") == "Disk: RL02 on the RLV12 at 174400, blocks 0-10239."
    for n in (115, 105, 10239, 0, 31):
        m.send(f"{n} BUFFER DROP UPDATE FLUSH")
        assert m.send("4 RL-DO DROP RLMP @ 6 RSHIFT .").split() == [str(n // 10)]


def test_update_in_a_loaded_block_marks_the_block_asked_for(image, boot):
    # Parsing the rest of the line re-reads the source block (SOURCE); that
    # must not make UPDATE mark the block being loaded instead of block 100.
    put_block(image, 70, ["CHAR A 100 BLOCK C!  UPDATE"])
    source = get_block(image, 70)
    m = boot()
    m.send("70 LOAD FLUSH")
    m.close()
    assert get_block(image, 100)[:1] == b"A"
    assert get_block(image, 70) == source


def test_a_controller_that_never_finishes_is_an_error_not_a_hang(tmp_path):
    # SIMH's seek time per cylinder raised so far that a full-stroke seek takes
    # 51 million instructions: the driver gives up (65536 polls) and says so.
    with Machine(disk=blank_disk(tmp_path / "slow.dsk"),
                 extra_commands="deposit rl stime 100000\n") as m:
        r = m.reply("10239 BLOCK")
        assert not r.ok and r.error.startswith("block read error")
        assert "RL0 block 10239 read timed out: CSR=" in r.output
        assert m.send("1 2 + .").split() == ["3"]


def test_a_block_that_loads_itself_ends_in_an_error(image, boot):
    put_block(image, 80, ["( runaway ) 80 LOAD"])
    m = boot()
    r = m.reply("80 LOAD")
    assert not r.ok and "overflow" in r.error and "in block 80 line 0" in r.error
    assert m.send("BLK @ . 1 2 + .").split() == ["0", "3"]
