"""Read a console script: FORTH lines, comments and directives (docs/console.md).

    # a comment: '#' then a blank, another '#' or nothing
    1000 LOAD                       a FORTH line, typed as it stands
    #wait 2.5                       2.5 simulated seconds pass with no input
    #simh show plant                a SIMH command (SHOW, SET, EXAMINE, DEPOSIT)

Blank lines are skipped. A '#' followed by a letter starts a directive, and an
unknown one is an error (a misspelt #wait must not pass silently as a comment).
Pure logic: parse(text, name) -> [Step]; ScriptSyntaxError names file:line.
"""
import math
import re
from dataclasses import dataclass
from pathlib import Path

MAX_WAIT = 3600.0            # simulated seconds in one #wait
SIMH_VERBS = ("show", "set", "examine", "deposit")   # commands that do not run the machine
MAX_LINE = 255               # what the kernel's ACCEPT takes (TIB-SIZE - 1, build/kernel.map)


class ScriptSyntaxError(ValueError):
    """The script cannot be read or a line of it is malformed."""


@dataclass(frozen=True)
class Step:
    lineno: int
    kind: str         # "forth", "wait" or "simh"
    text: str         # the FORTH line or the SIMH command
    seconds: float = 0.0


def _simh_command(arg, where):
    verb = arg.split(None, 1)[0].lower() if arg.strip() else ""
    # SIMH takes abbreviations: E and D, or two letters or more of a permitted verb
    allowed = verb in ("e", "d") or (len(verb) >= 2 and any(v.startswith(verb)
                                                             for v in SIMH_VERBS))
    if not allowed:
        raise ScriptSyntaxError(f"{where}: #simh takes one of {', '.join(SIMH_VERBS)} "
                                f"(commands that leave the machine stopped), not {arg!r}")
    return arg.strip()


def _wait_seconds(arg, where):
    try:
        seconds = float(arg)
    except ValueError:
        seconds = math.nan
    if not (0 < seconds <= MAX_WAIT):
        raise ScriptSyntaxError(f"{where}: #wait takes simulated seconds, 0 < s <= "
                                f"{MAX_WAIT:g}, not {arg!r}")
    return seconds


def _directive(lineno, body, where):
    name, _, arg = body.partition(" ")
    name = name.lower()
    if name == "wait":
        return Step(lineno, "wait", body, _wait_seconds(arg.strip(), where))
    if name == "simh":
        return Step(lineno, "simh", _simh_command(arg, where))
    raise ScriptSyntaxError(f"{where}: unknown directive #{name} (directives: #wait, "
                            "#simh; a comment is '#' followed by a blank)")


def _forth_line(lineno, line, where):
    if len(line) > MAX_LINE:
        raise ScriptSyntaxError(f"{where}: line of {len(line)} characters; the FORTH "
                                f"takes at most {MAX_LINE}")
    bad = [c for c in line if not (32 <= ord(c) < 127 or c == "\t")]
    if bad:
        raise ScriptSyntaxError(f"{where}: character {bad[0]!r} cannot be typed at "
                                "the console (printable ASCII and tab only)")
    return Step(lineno, "forth", line)


def parse(text, name="script"):
    steps = []
    for lineno, line in enumerate(text.splitlines(), 1):
        where = f"{name}:{lineno}"
        line = line.rstrip()
        stripped = line.lstrip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            body = stripped[1:]
            if re.match(r"[A-Za-z]", body):
                steps.append(_directive(lineno, body, where))
            continue
        steps.append(_forth_line(lineno, line, where))
    return steps


def read(path):
    """Parse the script at `path`; ScriptSyntaxError if missing or unreadable."""
    path = Path(path)
    try:
        text = path.read_bytes().decode("ascii")
    except OSError as e:
        raise ScriptSyntaxError(f"{path}: cannot read the script: {e.strerror}") from e
    except UnicodeDecodeError as e:
        raise ScriptSyntaxError(f"{path}: not an ASCII text file (byte {e.start})") from e
    return parse(text, str(path))
