"""Reference (b): SIMH's own PDP-11 disassembler (EXAMINE -M) reading words back."""
import re
import subprocess

from harness.machine.build import PDP11_STOCK as STOCK

from .corpus import ORIGIN

LINE = re.compile(r"^([0-7]+):\t(.*)$")
# Spellings SIMH never prints, and the one it prints instead.
ALIASES = {"BHIS": "BCC", "BLO": "BCS", "R6": "SP", "R7": "PC"}


def normalise(statement):
    """One MACRO-11 statement in SIMH's spelling: upper case, no blanks, aliases resolved."""
    text = re.sub(r"\s+", " ", statement.strip().upper())
    mnemonic, _, operands = text.partition(" ")
    tokens = re.split(r"([A-Z0-9]+)", operands.replace(" ", ""))
    operands = "".join(ALIASES.get(t, t) for t in tokens)
    return f"{ALIASES.get(mnemonic, mnemonic)} {operands}".strip()


def disassemble(units_words, simulator=STOCK, timeout=60):
    """For each list of words (placed at ORIGIN), SIMH's disassembly: a list of
    statements, normalised. One simulator run for all of them."""
    script = ["set cpu 11/23"]
    for words in units_words:
        last = ORIGIN + 2 * max(len(words), 1) - 2
        script.append(f"deposit {ORIGIN:o}-{last + 16:o} 0")
        script += [f"deposit {ORIGIN + 2 * i:o} {w:o}" for i, w in enumerate(words)]
        script.append(f"examine -m {ORIGIN:o}-{last:o}")
    script.append("quit")
    out = subprocess.run([str(simulator)], input="\n".join(script) + "\n", text=True,
                         capture_output=True, timeout=timeout).stdout
    units, current = [], None
    for line in out.splitlines():
        m = LINE.match(line.split("sim> ")[-1])
        if not m:
            continue
        if int(m.group(1), 8) == ORIGIN:
            current = []
            units.append(current)
        current.append(normalise(m.group(2)))
    if len(units) != len(units_words):
        raise RuntimeError(f"SIMH disassembled {len(units)} units, expected "
                           f"{len(units_words)}:\n{out[-2000:]}")
    return units
