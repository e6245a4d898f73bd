"""A breakpoint on a FORTH word from the page, and the instructions before it.

The page names a word; the lab finds its code field in the dictionary (the front
panel's WordIndex), stops the machine (^E), and types at sim> SET CPU HISTORY (the
last HISTORY instructions kept), BREAK at that address and CONT. When SIMH reports
the breakpoint, the lab types SHOW CPU HISTORY and sends the page its lines, each
with the FORTH word its PC lies in. Every line is one the page's own sim> allows
(sim_commands.refusal), and goes through the same guard. Pure logic here; the
typing is session.Simulator.simh_lines.
"""
import re

from harness.lab.sim_commands import refusal

HISTORY = 64                      # SIMH's least (HIST_MIN); enough to see the way in
SHOWN = 24                        # history lines sent to the page
HIT = re.compile(rb"Breakpoint, PC: ([0-7]{6})")
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


def clear_lines():
    return ["nobreak all", "cont"]


def named_history(text, index):
    """SHOW CPU HISTORY's rows with the word each PC lies in: [(pc, psw, what, word)]."""
    rows = []
    for line in text.splitlines():
        m = HISTORY_ROW.match(line.strip())
        if m:
            pc = int(m.group(1), 8)
            rows.append((m.group(1), m.group(2), m.group(3).strip(), index.containing(pc)))
    return rows[-SHOWN:]
