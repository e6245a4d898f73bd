"""Random and malformed lab messages (issue 23): each must be refused by
harness/lab/protocol.py with one error, and change nothing.

    python -m harness.fuzz.protocol_fuzz --messages N --seed S   (make fuzz)

sends them to a lab of its own over one websocket, then checks that every one
got exactly one error, the socket stayed open, the lab still answers a typed
line and its log holds no traceback. tests/lab/test_lab_keys.py runs a short
version in make test."""
import argparse
import asyncio
import json
import random
import sys
import tempfile

from harness.lab import protocol
from harness.lab.launch import LabProcess
from harness.lab.page_client import Page

ODD_VALUES = [None, True, False, 0, -1, 1.5, 2 ** 70, "", "x" * 50, [], [1], {}, {"a": 1},
              "real\u0000", "\u2603", [["deep"]], "key", {"t": "key"}]


def _value(rng):
    if rng.random() < 0.1:
        return "z" * rng.choice([protocol.MAX_KEYS + 1, 10000])
    return rng.choice(ODD_VALUES)


def _object(rng):
    """A JSON object that is not one of the protocol's messages."""
    kinds = list(protocol.FROM_PAGE)
    shape = rng.randrange(6)
    if shape == 0:
        return {"d": _value(rng)}                                 # no kind
    if shape == 1:
        return {"t": rng.choice([_value(rng), "Key", "speedy", "ended", "hello", "error"])}
    kind = rng.choice(kinds)
    message = {"t": kind, **{name: "x" for name in protocol.FROM_PAGE[kind]}}
    if shape == 2 and protocol.FROM_PAGE[kind]:
        del message[rng.choice(list(protocol.FROM_PAGE[kind]))]   # a field missing
    elif shape == 3:
        message[rng.choice(["v", "d", "x", "token", "__proto__"])] = _value(rng)
    else:                                                         # a value out of its rule
        fields = list(protocol.FROM_PAGE[kind]) or ["v"]
        message[rng.choice(fields)] = _value(rng)
    return message


def bad_message(rng):
    """One message text the protocol must refuse."""
    while True:
        shape = rng.randrange(10)
        if shape == 0:
            text = "".join(chr(rng.randrange(1, 0x3000)) for _ in range(rng.randrange(1, 40)))
        elif shape == 1:
            text = json.dumps(_object(rng))[:rng.randrange(1, 30)]     # cut short
        elif shape == 2:
            text = json.dumps(rng.choice([1, "key", [{"t": "pause"}], None, 3.5]))
        elif shape == 3:
            depth = rng.choice([100, 5000])
            text = "[" * depth + "]" * depth
        elif shape == 4 and rng.random() < 0.1:
            text = json.dumps({"t": "key", "d": "y" * (protocol.MAX_MESSAGE + 10)})
        else:
            text = json.dumps(_object(rng))
        try:
            protocol.parse(text)
        except protocol.Refused:
            return text                      # else it happened to be valid: draw again


async def fuzz_socket(server, n, seed):
    """Send n bad messages over one websocket; the number of errors received."""
    rng = random.Random(seed)
    page = await Page.open(server)
    status = dict(page.messages[0]["status"])
    for _ in range(n):
        await page.send(bad_message(rng))
    await page.until(lambda m: page.count.get("error", 0) >= n, 600)
    errors = page.count.get("error", 0)
    await page.type("2 3 + .\r", "5  ok")
    last = [m["status"] for m in page.messages if m["t"] == "data"]
    speed = last[-1]["speed"] if last else status["speed"]
    await page.close()
    return errors, speed == status["speed"]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--messages", type=int, default=50000)
    parser.add_argument("--seed", type=int, default=1983)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        server = LabProcess(tmp)
        try:
            errors, same = asyncio.run(fuzz_socket(server, args.messages, args.seed))
        finally:
            status = server.stop()
        clean = "Traceback" not in server.text() and status == 0
    print(f"protocol fuzz: {args.messages} malformed messages (seed {args.seed}): {errors} "
          f"errors back, speed {'unchanged' if same else 'CHANGED'}, lab exit {status}, "
          f"{'no traceback' if clean else 'TRACEBACK or bad exit in the log'}")
    return 0 if errors == args.messages and same and clean else 1


if __name__ == "__main__":
    sys.exit(main())
