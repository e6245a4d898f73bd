"""The console's watcher (harness/machine/console_watch.py), SIMH's command lookup
(harness/machine/simh_command.py), the buffer tables (harness/machine/block_buffers.py) and the
report of leaving (harness/console_session.Departure), as pure logic."""
from pathlib import Path

import pytest

from harness.machine import block_buffers
from harness.machine.console_session import Departure
from harness.machine.console_watch import Leave, LineWatcher
from harness.machine.simh_command import simh_command


@pytest.mark.parametrize("line,command", [("q", "QUIT"), ("quit", "QUIT"), ("EXI", "EXIT"),
                                          ("e 1000", "EXAMINE"), ("ex", "EXAMINE"),
                                          ("b", "BOOT"), ("by", "BYE"), ("c", "CONT"),
                                          ("  show plant", "SHOW"), ("s", "STEP"),
                                          ("; quit", None), ("", None), ("zap", None)])
def test_simh_command_follows_scps_table_order(line, command):
    assert simh_command(line) == command


def at_simh():
    w = LineWatcher()
    w.output(b"\r\nSimulation stopped, PC: 005742 (BEQ 5734)\r\nsim")
    w.output(b"> ")                     # the prompt split over two reads
    assert w.at_simh
    return w


def way_out(watcher, data):
    with pytest.raises(Leave) as way:
        watcher.feed(data)
    return way.value


def test_the_halt_of_the_bye_word_leaves_even_split_over_reads():
    w = LineWatcher(b"HALT instruction, PC: 043644")
    assert w.output(b"1 \r\nHALT instruction, PC: 0436") == b"1 \r\nHALT instruction, PC: 0436"
    with pytest.raises(Leave) as way:
        w.output(b"44 (JMP @(R4)+)\r\nsim> ")
    assert way.value.how == "the BYE word"
    other = LineWatcher(b"HALT instruction, PC: 043644")   # another HALT is no way out
    other.output(b"\r\nHALT instruction, PC: 001000 (HALT)\r\nsim> ")
    assert other.at_simh


def test_bye_and_ctrl_d_leave_anywhere_and_keep_what_was_typed_ahead():
    way = way_out(LineWatcher(), b"1 2 + .\r  bye\r")
    assert way.how == "BYE" and way.typed == b"1 2 + .\r  bye"
    assert way_out(LineWatcher(), b"\x04").how == "^D"


def test_at_the_forth_ctrl_c_and_quit_are_the_forths():
    w = LineWatcher()
    assert w.feed(b"\x03quit\r") == b"\x03quit\r"


def test_at_simh_ctrl_c_leaves_and_simhs_own_quit_goes_to_simh():
    """SIMH's QUIT, EXIT and BYE FLUSH inside the simulator (leave_check.c), however
    the line was edited: the watcher lets them through."""
    assert way_out(at_simh(), b"\x03").how == "^C at SIMH's prompt"
    assert at_simh().feed(b"q\r") == b"q\r"
    assert at_simh().feed(b"exix\x7ft\r") == b"exix\x7ft\r"


def test_cont_gives_the_keyboard_back_to_the_forth():
    w = at_simh()
    assert w.feed(b"show clk\r") == b"show clk\r" and w.at_simh
    w.feed(b"c\r")
    assert not w.at_simh
    assert w.feed(b"\x03") == b"\x03"
    w.output(b"\r\nsim> ")              # ^E again
    assert way_out(w, b"\x03")


def test_unwritten_blocks_are_the_updated_assigned_ones():
    assert block_buffers.unwritten([100, 0o177777, 7, 3000], [0o177777, 0o177777, 0, 1]) \
        == [100, 3000]
    symbols = {"BUF-BLK": 0o33724, "BUF-UPD": 0o33752}
    assert block_buffers.table_command(symbols, "BUF-UPD") == "examine 33756:33764"
    outputs = {"examine 33730:33736": "33730:\t000144\r\n33732:\t177777\r\n"
                                      "33734:\t177777\r\n33736:\t177777\r\n",
               "examine 33756:33764": "33756:\t177777\r\n33760:\t0\r\n33762:\t0\r\n"
                                      "33764:\t0\r\n"}
    assert block_buffers.read_unwritten(symbols, outputs.get) == [100]
    assert block_buffers.read_unwritten(symbols, lambda c: "Non-existent") is None


def test_the_report_says_what_happened():
    disk = Path("w.dsk")
    good = Departure(disk, flush="ok", unwritten=[], detach="ok")
    assert good.safe and good.report() == [
        "FLUSH answered ok: every UPDATEd block is written to w.dsk and synced to the "
        "host's disk.", "Disk w.dsk detached."]
    bad = Departure(disk, flush="failed (Error: block write error: FLUSH)",
                    unwritten=[3000, 3001, 7], detach="Unit not attached")
    assert not bad.safe and bad.report() == [
        "FLUSH failed (Error: block write error: FLUSH).",
        "NOT SAVED: block(s) 7, 3000-3001: UPDATEd, and FLUSH did not complete their "
        "write; the changes may be lost.",
        "Disk w.dsk not detached: Unit not attached."]
    unknown = Departure(disk, flush="was not answered within 60 s (the FORTH is busy)")
    assert "may not be written" in unknown.report()[1]
