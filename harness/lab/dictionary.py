"""Find FORTH words' bodies in a copy of the machine's memory (pure logic).

The header layout is harness.machine.kernel_layout's; a vocabulary's body holds
the newest LFA of each of its chains (kernel_layout.chain_of). CREATE, VAR
and ARRAY words keep their values in the body.
"""
import struct

from harness.machine.kernel_layout import CHAINS, LENGTH, SMUDGE, body_of

MAX_HEADERS = 20000            # a broken chain must not loop for ever
SPACE = 1 << 16                # the FORTH's 16-bit addresses (grown if a dump goes above)


class Memory:
    """16-bit words by even address, filled from dumps; bytes read little-endian.
    Held as the machine holds them, bytes beside a map of the bytes known, so a
    header's name is one slice (a lab's start walks some 1 200 headers twice)."""

    def __init__(self):
        self.data = bytearray(SPACE)
        self.known = bytearray(SPACE)           # 1 where a dump has said the byte

    def store(self, address, words):
        end = address + 2 * len(words)
        if end > len(self.data):
            self.data += bytes(end - len(self.data))
            self.known += bytes(end - len(self.known))
        self.data[address:end] = struct.pack(f"<{len(words)}H", *words)
        self.known[address:end] = b"\1" * (end - address)

    def word(self, address):
        a = address & ~1
        if a + 1 >= len(self.data) or not self.known[a]:
            return None
        return self.data[a] | self.data[a + 1] << 8

    def byte(self, address):
        one = self.bytes(address, 1)
        return one[0] if one else None

    def bytes(self, address, n):
        """The n bytes from `address`, or None unless all are known."""
        if address + n > len(self.data) or self.known.find(0, address, address + n) >= 0:
            return None
        return bytes(self.data[address:address + n])


def header_name(memory, lfa):
    """The name at header `lfa` and its flags byte, or (None, 0) if not in memory."""
    count = memory.byte(lfa + 2)
    if count is None:
        return None, 0
    name = memory.bytes(lfa + 3, count & LENGTH)
    if name is None:
        return None, 0
    return name.decode("latin-1"), count


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
