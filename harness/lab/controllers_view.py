"""The five machines as the lab's controllers page shows them (pure logic): the
lock-step coordinator's status (its --status file: time, members, per axis the
plant and the words that last crossed the link each way) and each 11/03's
console log, turned into one JSON-ready view.

The servo table per axis is read off the link traffic, decoded with the link
protocol of docs/controllers.md ("The link protocol"): a command word 122400 +
code, then its value, answered by the 11/03. Shown per axis: the target last
sent (Abs.Move.Single) and the maximum velocity last sent (from the status's
"sent", the value the coordinator keeps per command: the last eight words are
soon status polls only, Move.Complete? sends one after another), the last status
answer (bit 0 a command executing, bit 1 moving), and from the plant the
counter, position, velocity and the D/A code the 11/03's servo holds.
"""
COMMAND_BASE = 0o122400
COMMANDS = {1: "move", 2: "max_vel", 3: "set_up", 4: "status", 5: "counter", 6: "output",
            7: "zero"}
MEMBERS = ("x", "y", "z", "t", "main")
TAIL_LINES = 6


def commands(to_11_03):
    """[(quantum, name, value)] from the words sent to an 11/03: command then value."""
    found, pending = [], None
    for quantum, word in to_11_03:
        code = word - COMMAND_BASE
        if pending is None and code in COMMANDS:
            pending = (quantum, COMMANDS[code])
        elif pending is not None:
            found.append((*pending, word))
            pending = None
    return found


def servo_row(axis):
    """One axis's line of the servo table."""
    sent = commands(axis["to_11_03"])
    last = {COMMANDS[int(code)]: value for code, value in axis["sent"].items()
            if int(code) in COMMANDS}
    answers = [word for _, word in axis["to_11_23"]]
    status_answers = [a for (_, name, _), a in zip(sent[-len(answers):], answers[-len(sent):])
                      if name == "status"] if sent and answers else []
    status = status_answers[-1] if status_answers else None
    return {"axis": axis["axis"], "target": signed(last.get("move")),
            "max_vel": last.get("max_vel"),
            "executing": None if status is None else bool(status & 1),
            "moving": None if status is None else bool(status & 2),
            "counter": axis["counter"], "pos": axis["pos"], "vel": axis["vel"],
            "dac": axis["dac"], "run": axis["run"],
            "last_words": [f"{w:06o}" for _, w in axis["to_11_03"][-4:]],
            "last_answers": [f"{w:06o}" for _, w in axis["to_11_23"][-4:]]}


def signed(word):
    return None if word is None else (word - 0o200000 if word & 0o100000 else word)


def tail(text, lines=TAIL_LINES):
    shown = [line for line in text.replace("\r", "").split("\n")]
    return "\n".join(shown[-lines:])


def view(status, logs):
    """status: the coordinator's status (dict) or None (not written yet); logs:
    member -> its console's text so far (the 11/03s' and the 11/23's main.log)."""
    if status is None:
        return {"started": False}
    return {"started": True, "time_s": status["time_s"], "quantum": status["quantum"],
            "rack_on": bool(status["power"]),   # SET PLANT POWER at any machine's sim>
            "machines": [{"name": m, "state": status["members"].get(m, "absent"),
                          "console": tail(logs.get(m, ""))} for m in MEMBERS],
            "servo": [servo_row(a) for a in status["axes"]]}
