"""The lab's protocol, defined once (harness/lab/protocol.py): what it refuses, and
the page's own messages and the server's dispatch checked against it."""
import random
import re

import pytest

from harness.fuzz.protocol_fuzz import bad_message
from harness.lab import protocol
from harness.lab.server import Lab
from harness.lab.server import STATIC


@pytest.mark.parametrize("text, why", [
    ('{"t":"speed","v":[1]}', "speed: field 'v' is [1], not one of"),   # issue 23's traceback
    ('{"t":"speed","v":"fast"}', "not one of"),
    ('{"t":"key","d":5}', "field 'd' is int, not str"),
    ('{"t":"key"}', "field 'd' missing"),
    ('{"t":"pause","x":1}', "unknown field 'x'"),
    ('{"t":"launch"}', "unknown message kind"),
    ('{"t":["key"]}', "unknown message kind"),
    ('[1,2]', "a message is a JSON object, not list"),
    ('{"t":"key","d":"', "not JSON"),
    ("[" * 5000 + "]" * 5000, ""),
    ('{"t":"power","v":true}', "not one of"),
])
def test_bad_messages_are_refused_with_a_reason(text, why):
    with pytest.raises(protocol.Refused) as refused:
        protocol.parse(text)
    assert why in str(refused.value)


def test_a_key_message_is_at_most_max_keys_long():
    assert protocol.parse('{"t":"key","d":"%s"}' % ("a" * protocol.MAX_KEYS))[0] == "key"
    with pytest.raises(protocol.Refused):
        protocol.parse('{"t":"key","d":"%s"}' % ("a" * (protocol.MAX_KEYS + 1)))


def test_the_servers_dispatch_is_the_protocols():
    """Every kind the page may send has its handler, and no handler is outside it."""
    handlers = {name[3:] for name in dir(Lab) if name.startswith("on_")}
    assert set(protocol.FROM_PAGE) <= handlers
    assert handlers - set(protocol.FROM_PAGE) == {"console", "lab", "ended", "text"}


def test_the_pages_messages_are_the_protocols():
    """Every message the page's scripts (lab.js and its panels' lab-*.js) send names
    a kind of FROM_PAGE with exactly its fields, and every kind they read is one of
    TO_PAGE."""
    source = "".join(path.read_text() for path in sorted(STATIC.glob("lab*.js")))
    sent = re.findall(r"send\(\{ t: ([^}]*)\}\)", source)
    assert len(sent) >= 6
    kinds = set()
    for body in sent:
        kind = re.match(r'"(\w+)"|lab\.status\.[\w =|".]+ \? "run" : "pause"', body)
        names = {"run", "pause"} if kind.group(1) is None else {kind.group(1)}
        fields = set(re.findall(r",\s*(\w+)(?::|\s*$)", body))
        for name in names:
            assert name in protocol.FROM_PAGE, name
            assert fields == set(protocol.FROM_PAGE[name]), (name, fields)
        kinds |= names
    assert kinds == set(protocol.FROM_PAGE)
    read = set(re.findall(r'm\.t === "(\w+)"', source))
    assert read == set(protocol.TO_PAGE), read ^ set(protocol.TO_PAGE)


def test_the_fuzz_draws_only_refused_messages():
    rng = random.Random(5)
    for _ in range(2000):
        with pytest.raises(protocol.Refused):
            protocol.parse(bad_message(rng))
