"""The lab's protocol, defined once: every message between the page and the
server, its kind (`t`) and its fields. The server's dispatch takes its kinds from
FROM_PAGE and checks every message against it (check); tests check the page's
own messages and the server's against the tables.

A field's rule is a type (the value must be of exactly that type: True is not an
int), a tuple of allowed values, or a Rule. A message with another kind, a
missing or an extra field, or a value outside its rule is refused (Refused,
with why); the server answers it with one `error` message and changes nothing.
"""
import json
from dataclasses import dataclass

MAX_KEYS = 4096              # characters in one `key` message: the page sends a paste in pieces
MAX_MESSAGE = 1 << 16        # bytes in one message from a page


@dataclass(frozen=True)
class Rule:
    kind: type
    most: int = None                     # longest text or list
    nullable: bool = False

    def why_not(self, value):
        if value is None and self.nullable:
            return None
        if type(value) is not self.kind:
            return f"is {type(value).__name__}, not {self.kind.__name__}"
        if self.most is not None and len(value) > self.most:
            return f"is {len(value)} long, more than {self.most}"
        return None


FROM_PAGE = {
    "key": {"d": Rule(str, MAX_KEYS)},           # typed or pasted text (the keyboard's holder)
    "take": {},                                  # take the keyboard
    "speed": {"v": ("real", "x10", "full")},
    "power": {"v": ("on", "off")},
    "clock": {"v": ("count", "timed")},          # the time base (SET CLK TIMED)
    "pause": {},
    "run": {},
    "step": {},
    "stepi": {},                                 # one instruction, at sim> (breakpoints.py)
    "break": {"word": Rule(str, 31)},            # a breakpoint on a FORTH word (breakpoints.py)
    "iobreak": {"address": Rule(str, 8)},        # ... on an I/O register's access (octal)
    "nobreak": {},
    "program": {"block": int},                   # a block and its listing (program_pane.py)
    "check": {"exercise": (1, 2, 3, 4, 5)},      # run docs/exercises.md's check (lesson_checks.py)
}

TO_PAGE = {
    "hello": {"stops": dict, "plant": dict, "per_axis": list, "single": list, "status": dict,
              "con": str, "keyboard": dict},
    "con": {"d": str},                                   # console output
    "data": {"rows": list, "status": dict, "servo": dict,
             "panel": Rule(dict, nullable=True),          # the 11/23's front panel
             "ticks": list},                              # [time_s, words] where they changed
    "history": {"rows": list, "what": str,               # the instructions before a breakpoint
                "where": Rule(dict, nullable=True)},     # the stopped word's block and line
    "keyboard": {"holder": Rule(str, nullable=True), "you": bool},
    "input": {"waiting": int, "room": int},              # answer to `key`: the queue
    "error": {"why": str},
    "ended": {"safe": (True, False, None)},
    "program": {"block": int, "lines": list, "code": list,      # the program pane
                "why": Rule(str, nullable=True)},
    "checked": {"exercise": int, "text": str, "ok": (True, False, None)},   # a check's output
}


class Refused(ValueError):
    """A message that is not one of the protocol's; the text says why."""


def _why_not(rule, value):
    if isinstance(rule, Rule):
        return rule.why_not(value)
    if isinstance(rule, tuple):
        if any(type(value) is type(option) and value == option for option in rule):
            return None
        return f"is {json.dumps(value)[:40]}, not one of {', '.join(json.dumps(o) for o in rule)}"
    if type(rule) is type:
        return None if type(value) is rule else f"is {type(value).__name__}, not {rule.__name__}"
    raise TypeError(f"bad rule {rule!r}")


def check(message, table=FROM_PAGE):
    """The message's kind when it is one of `table`'s; else Refused."""
    if type(message) is not dict:
        raise Refused(f"a message is a JSON object, not {type(message).__name__}")
    kind = message.get("t")
    if type(kind) is not str or kind not in table:
        raise Refused(f"unknown message kind {json.dumps(kind)[:40]}")
    fields = table[kind]
    extra = sorted(set(message) - set(fields) - {"t"})
    if extra:
        raise Refused(f"{kind}: unknown field {extra[0][:40]!r}")
    for name, rule in fields.items():
        if name not in message:
            raise Refused(f"{kind}: field {name!r} missing")
        why = _why_not(rule, message[name])
        if why:
            raise Refused(f"{kind}: field {name!r} {why}")
    return kind


def parse(text):
    """A page's message (JSON text) checked: (kind, message); else Refused."""
    if len(text) > MAX_MESSAGE:
        raise Refused(f"a message of {len(text)} characters: at most {MAX_MESSAGE}")
    try:
        message = json.loads(text)
    except (ValueError, RecursionError) as err:
        raise Refused(f"not JSON ({str(err)[:60]})") from None
    return check(message), message


# ---- the LAB device (pdp11-devices/lab/lab.c): the server's side of its FIFOs -------
# Commands the server writes to LAB's command FIFO, one a line: name -> its arguments
# as the device's help names them. lab.c answers an unknown command with
# "E,commands: ..." built from the same list (tests/lab/test_lab_device.py holds
# the two together, and the header comment of lab.c with them).
DEVICE_COMMANDS = {
    "speed": "X",             # pace at X times the 11/23's; 0 = full speed
    "pause": "",              # stop simulated time at the next tick
    "run": "",                # go on
    "step": "",               # one tick more, then pause
    "watch": "ADDR...",       # octal even addresses below 160000, at most 64
    "dump": "ADDR N",         # N words from octal ADDR
    "power": "on|off",        # the amplifier rack's switch (SET PLANT POWER)
    "panel": "[ADDR...|off]", # R rows: the 11/23's front panel (front_panel.py)
    "halt": "",               # to sim> at the next tick, paused or not
    "clock": "count|timed",   # the time base (SET CLK TIMED), where the CPU prices
}

# Rows the device writes, one a line: kind -> its fields (a trailing "..." repeats).
DEVICE_ROWS = {
    "W": ("time_s", "tick", "w0", "..."),          # every reported tick: watched words
    "P": ("time_s", "axis", "..."),                # the plant trace's row (plant_rows.COLUMNS)
    "A": ("a0", "..."),                            # the watched addresses (octal)
    "S": ("time_s", "state", "speed", "power", "clock", "timable"),   # after every command
    "M": ("addr", "w0", "..."),                    # a dump, up to 64 words a row
    "R": ("time_s", "r0", "..."),                  # the front panel (front_panel.py)
    "I": ("time_s", "vector=count", "..."),        # interrupts taken, with each R row
    "E": ("what",),                                # a refused command
}


def device_help():
    """The list lab.c's refusal of an unknown command gives."""
    return ", ".join(f"{name} {args}".rstrip() for name, args in DEVICE_COMMANDS.items())


def device_command(text):
    """`text` when its first word is one of the LAB device's commands; else Refused
    (the server never writes a line the device would only refuse)."""
    name = text.split(" ", 1)[0]
    if name not in DEVICE_COMMANDS:
        raise Refused(f"the LAB device has no command {name!r} (commands: {device_help()})")
    return text
