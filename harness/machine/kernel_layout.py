"""The FORTH kernel's layout as the harness reads it: the one home for it.

build/kernel.map (written by the metacompiler, forth/meta/) has a line
"OOOOOO NAME" (octal address) for each word and label of the kernel. A word's
header (forth/README.md) is: LFA (link to the previous header of its chain),
the count byte (bit 5 SMUDGE, bits 4-0 the name's length), the name padded to
an even address, the 4-byte code field (JSR Rn,@#DOVAR and the like), the body:
a CREATE, VAR or ARRAY word's data (>BODY).

    symbols = read_kernel_map()            # NAME -> address (first of a name wins)
    symbols["DP"] + BODY                   # where DP's value is
    entry(path)                            # ENTRY (the cold start), or None
"""
import re
from pathlib import Path

from harness.machine.build import KERNEL_MAP

BODY = 4                  # code field to data: >BODY
SMUDGE, LENGTH = 0o40, 0o37
CHAINS = 32               # a vocabulary's body: the newest LFA of each chain (chain_of);
                          # the map's #CHAINS (forth/meta/meta.fs) must agree: read_kernel_map
_MAP_LINE = re.compile(r"[0-7]+")


class KernelMapError(RuntimeError):
    """The kernel map is missing, unreadable, or lacks a symbol the caller needs."""


def map_lines(path=KERNEL_MAP):
    """(address, NAME as written) for each symbol line of the map, in order;
    KernelMapError if it cannot be read."""
    try:
        text = Path(path).read_text()
    except OSError as e:
        raise KernelMapError(f"cannot read the kernel map {path}: {e.strerror}: run make") from e
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 2 and _MAP_LINE.fullmatch(parts[0]):
            yield int(parts[0], 8), parts[1]


def read_kernel_map(path=KERNEL_MAP, required=()):
    """NAME (upper case) -> address for every symbol of the map (a name defined
    twice keeps its first address); KernelMapError if one of `required` is missing."""
    symbols = {}
    for address, name in map_lines(path):
        symbols.setdefault(name.upper(), address)
    missing = [s for s in required if s not in symbols]
    if missing:
        raise KernelMapError(f"{path} lacks {', '.join(missing)}: a kernel this harness "
                             "does not know how to drive")
    if symbols.get("#CHAINS", CHAINS) != CHAINS:
        raise KernelMapError(f"{path}: the kernel hashes names into {symbols['#CHAINS']} chains "
                             f"per word list, this harness into {CHAINS} (kernel_layout.CHAINS)")
    return symbols


def map_names(path=KERNEL_MAP):
    """address -> name for every line of the map (a name defined twice, in two
    vocabularies, has two addresses; an address named twice keeps the later name)."""
    return dict(map_lines(path))


def entry(path=KERNEL_MAP):
    """ENTRY's address (the kernel's cold start), or None if the map cannot say."""
    try:
        return read_kernel_map(path).get("ENTRY")
    except KernelMapError:
        return None


def chain_of(name):
    """The chain of a word list that a header named `name` is linked into: its
    upper-cased first character plus twice its length, mod CHAINS (the kernel's
    CHAIN-OFFSET, the metacompiler's name-chain)."""
    first = name.encode("latin-1")[0]
    if ord("a") <= first <= ord("z"):
        first -= 32
    return (first + 2 * len(name)) % CHAINS


def code_field(lfa, length):
    """The code field of the header at `lfa` whose name has `length` characters:
    link, count byte, name, padded to an even address."""
    return (lfa + 3 + length + 1) & ~1


def body_of(lfa, length):
    """The body (>BODY) of the header at `lfa` whose name has `length` characters."""
    return code_field(lfa, length) + BODY
