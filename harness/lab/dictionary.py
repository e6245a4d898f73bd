"""Find FORTH words' bodies in a copy of the machine's memory (pure logic).

The header layout is harness.machine.kernel_layout's; a vocabulary's body holds
the newest LFA of each of its chains (kernel_layout.chain_of). CREATE, VAR
and ARRAY words keep their values in the body.
"""
from harness.machine.kernel_layout import CHAINS, LENGTH, SMUDGE, body_of

MAX_HEADERS = 20000            # a broken chain must not loop for ever


class Memory:
    """Words by even address, filled from dumps; bytes read little-endian."""

    def __init__(self):
        self.words = {}

    def store(self, address, words):
        for i, w in enumerate(words):
            self.words[address + 2 * i] = w

    def word(self, address):
        return self.words.get(address & ~1)

    def byte(self, address):
        w = self.word(address)
        return None if w is None else (w >> (8 * (address & 1))) & 0o377


def header_name(memory, lfa):
    """The name at header `lfa` and its flags byte, or (None, 0) if not in memory."""
    count = memory.byte(lfa + 2)
    if count is None:
        return None, 0
    chars = [memory.byte(lfa + 3 + i) for i in range(count & LENGTH)]
    if None in chars:
        return None, 0
    return bytes(chars).decode("latin-1"), count


def headers(memory, vocabulary_body):
    """(lfa, name, count byte) of each header in the vocabulary's chains,
    newest first in each chain, as far as `memory` holds them."""
    for chain in range(CHAINS):
        lfa, steps = memory.word(vocabulary_body + 2 * chain), 0
        while lfa and steps < MAX_HEADERS:
            name, count = header_name(memory, lfa)
            if name is None:
                break
            yield lfa, name, count
            lfa, steps = memory.word(lfa), steps + 1


def find_bodies(memory, vocabulary_body, names):
    """{name: body address} for each of `names` found (newest definition, case
    ignored as the FORTH's own lookup does) in the vocabulary's chains."""
    wanted = {n.upper(): n for n in names}
    found = {}
    for lfa, name, count in headers(memory, vocabulary_body):
        key = name.upper()
        if key in wanted and wanted[key] not in found and not count & SMUDGE:
            found[wanted[key]] = body_of(lfa, count & LENGTH)
    return found
