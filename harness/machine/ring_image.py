"""A typed-ahead line as an absolute-loader image, for SIMH's LOAD.

The lock-step driver (scripted_machine.py) puts each line and its CR into the
kernel's console receive ring and advances RXHEAD, as the DL11 receive
interrupt would have. One SIMH DEPOSIT per character cost some 5 us of the
simulator's command parsing each (it looks every address up as a register
name first), a third of a second in the fuzz's 2 000 lines; one LOAD of this
image makes the same memory writes at once. The format is the PDP-11 paper-tape
absolute loader's, as build/kernel.lda and SIMH's `load` read it: blocks of
1, 0, byte count (header included) and load address, both little-endian, the
data, and a checksum byte that makes the block's bytes sum to 0 mod 256; a block
of count 6 ends the image, at address 1 without setting the PC.
"""

END = bytes([1, 0, 6, 0, 1, 0, 0o370])     # count 6, address 1: stop, PC unchanged


def lda_block(address, data):
    """One data block loading `data` at `address`."""
    count = 6 + len(data)
    block = bytes([1, 0, count & 0o377, count >> 8, address & 0o377, address >> 8]) + data
    return block + bytes([-sum(block) & 0o377])


def ring_pieces(sym, text, head):
    """Where the line `text` and its CR go in the ring from index `head`:
    ([(address, bytes)], split where the ring wraps; RXHEAD after them)
    (sym: kernel.map). The one home of this arithmetic: ring_image() and
    scripted_machine.feed_commands() both write these."""
    mask, ring = sym["RING-MASK"], sym["RING"]
    data, at, pieces = (text + "\r").encode("latin-1"), head, []
    while data:
        piece, data = data[:mask + 1 - at], data[mask + 1 - at:]
        pieces.append((ring + at, piece))
        at = (at + len(piece)) & mask
    return pieces, at


def ring_image(sym, text, head):
    """(the LOAD image of ring_pieces(sym, text, head) and RXHEAD after them, its
    end block last; that RXHEAD)."""
    pieces, after = ring_pieces(sym, text, head)
    writes = pieces + [(sym["RXHEAD"], after.to_bytes(2, "little"))]
    return b"".join(lda_block(a, d) for a, d in writes) + END, after
