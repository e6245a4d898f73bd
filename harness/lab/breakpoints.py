"""Breakpoints from the page, the instructions before them, and one-instruction steps.

The page names a word; the lab finds its code field in the dictionary (the front
panel's WordIndex), stops the machine (the LAB device's `halt`, at a tick), and
types at sim> SET CPU HISTORY (the last HISTORY instructions kept), BREAK at that
address and CONT. Or it names an I/O register: SET LAB IOBREAK=address
(pdp11-devices/simh/io_break.c: SIMH's own breakpoints stop on execution only).
When SIMH reports either, the lab types SHOW CPU HISTORY and sends the page its
lines, each with the FORTH word its PC lies in. A step types STEP and SHOW LAB
PANEL (the front panel's R row after the instruction). Every line is one the
page's own sim> allows (sim_commands.refusal), and goes through the same guard.
Pure logic here; the typing is session.Simulator.simh_lines.
"""
import re

from harness.lab.sim_commands import refusal

HISTORY = 64                      # SIMH's least (HIST_MIN); enough to see the way in
SHOWN = 24                        # history lines sent to the page
HIT = re.compile(rb"Breakpoint, PC: ([0-7]{6})")
IO_HIT = re.compile(rb"(I/O break: [^\r\n]*) at PC ([0-7]{6})\r*\n")
IO_REFUSED = re.compile(r"IOBREAK: [^\r\n]*")
IO_PAGE = 0o160000, 0o200000      # the program's addresses of the I/O page
IO_PAGE_22 = 0o17760000           # the same registers as SIMH's 22-bit addresses
STEP_LINES = ["step", "show lab panel"]
HISTORY_ROW = re.compile(r"^([0-7]{6}) ([0-7]{6})\|(.*)$")
MAX_NAME = 31                     # a FORTH name's longest (the count byte's 5 bits)


def break_lines(index, name):
    """The sim> lines that break on `name`, or (None, why)."""
    if not isinstance(name, str) or not 0 < len(name) <= MAX_NAME or " " in name:
        return None, "a FORTH word's name: 1 to 31 characters, no blank"
    address = index.address_of(name)
    if address is None:
        return None, f"no word {name} in the dictionary"
    lines = [f"set cpu history={HISTORY}", "nobreak all", f"break {address:o}", "cont"]
    assert all(refusal(line) is None for line in lines)
    return lines, f"breakpoint on {name} at {address:06o}"


def iobreak_lines(text):
    """The sim> lines that break on an access to the I/O register at octal `text`,
    or (None, why). Whether a device answers there, SIMH says (io_break.c)."""
    if not re.fullmatch(r"[0-7]{1,8}", text.strip()):
        return None, f"an I/O register's address in octal, as 170440 (not {text.strip()[:12]!r})"
    address = int(text, 8)
    if address >= IO_PAGE_22:
        address += IO_PAGE[0] - IO_PAGE_22
    if not IO_PAGE[0] <= address < IO_PAGE[1] or address & 1:
        return None, f"{text.strip()} is not an even I/O page address (160000-177776)"
    lines = [f"set cpu history={HISTORY}", f"set lab iobreak={address:o}"]
    assert all(refusal(line) is None for line in lines)
    return lines, f"breakpoint on an access to {address:06o}"


def clear_lines():
    return ["nobreak all", "set lab noiobreak", "cont"]


def named_history(text, index):
    """SHOW CPU HISTORY's rows with the word each PC lies in: [(pc, psw, what, word)]."""
    rows = []
    for line in text.splitlines():
        m = HISTORY_ROW.match(line.strip())
        if m:
            pc = int(m.group(1), 8)
            rows.append((m.group(1), m.group(2), m.group(3).strip(), index.containing(pc)))
    return rows[-SHOWN:]
