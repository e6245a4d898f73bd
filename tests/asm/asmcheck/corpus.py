"""Corpus files: one unit per line, `FORTH text | MACRO-11 statements`.

Every unit is assembled at ORIGIN (001000). The MACRO-11 side uses octal
numbers, separates statements with ` ; `, and writes branch targets and
PC-relative operands as absolute octal addresses, the way SIMH prints them.
The FORTH side is what a user types: numbers with a trailing O are octal (the
target's syntax). `#` starts a comment line. An error corpus line is
`FORTH text | ! message` or `FORTH text | !n message`: the unit must abort
with that message, after n words (0 if absent) of the instructions before the
failing one: the failing instruction emits nothing."""
import re
from dataclasses import dataclass
from pathlib import Path

ORIGIN = 0o1000
ERROR = re.compile(r"^!(\d*)\s+(.*)$")
OCTAL_TOKEN = re.compile(r"^(-?)([0-7]+)O$")


@dataclass(frozen=True)
class Unit:
    source: str       # file:line, for messages
    forth: str
    macro: tuple      # MACRO-11 statements, empty for an error unit
    error: str = ""   # expected abort message, for an error unit
    emitted: int = 0  # words legitimately emitted before the error


def read(path):
    """The units of one corpus file, in order."""
    units = []
    for n, line in enumerate(Path(path).read_text().splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        if "|" not in line:
            raise ValueError(f"{path}:{n}: no '|' between FORTH and MACRO-11 text")
        forth, macro = (part.strip() for part in line.split("|", 1))
        where = f"{Path(path).name}:{n}"
        error = ERROR.match(macro)
        if error:
            units.append(Unit(where, forth, (), error.group(2), int(error.group(1) or 0)))
        else:
            units.append(Unit(where, forth, tuple(s.strip() for s in macro.split(" ; "))))
    return units


def forth_for_host(text):
    """The FORTH text with trailing-O octal literals made decimal (gforth lacks them)."""
    def convert(token):
        m = OCTAL_TOKEN.match(token)
        return f"{m.group(1)}{int(m.group(2), 8)}" if m else token
    return " ".join(convert(t) for t in text.split())
