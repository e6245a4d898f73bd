"""The scripted runs' line as one SIMH LOAD (harness/machine/ring_image.py) and as
per-character DEPOSITs (feed_commands, for the five machines and the benches):
both write the line, its CR and RXHEAD where the DL11's receive interrupt would
have (this file's own reference, the ring wrapping too), and every LOAD block's
checksum holds."""
import pytest

from harness.machine.ring_image import ring_image
from harness.machine.scripted_machine import END_WAIT, feed_commands

SYM = {"RING": 0o154400, "RING-MASK": 0o777, "RXHEAD": 0o154000}   # as kernel.map has them


def deposited(commands):
    """address -> byte after SIMH ran the DEPOSIT commands (words little-endian)."""
    memory = {}
    for command in commands:
        if command == END_WAIT:
            continue
        words = command.split()
        address, value = int(words[-2], 8), int(words[-1], 8)
        memory[address] = value & 0o377
        if words[1] != "-b":
            memory[address + 1] = value >> 8
    return memory


def loaded(image):
    """address -> byte after SIMH's LOAD (pdp11_sys.c's sim_load), checksums checked."""
    memory, at = {}, 0
    while True:
        assert image[at:at + 2] == b"\1\0"
        count, address = image[at + 2] | image[at + 3] << 8, image[at + 4] | image[at + 5] << 8
        if count == 6:
            assert address == 1              # the end: the PC is left alone
            return memory
        assert sum(image[at:at + count + 1]) % 256 == 0
        memory.update((address + i, b) for i, b in enumerate(image[at + 6:at + count]))
        at += count + 1


def interrupt_writes(text, head):
    """address -> byte as the receive interrupt leaves them: each character at RING
    + (index AND RING-MASK), then RXHEAD (a word) the index after the CR."""
    mask = SYM["RING-MASK"]
    memory = {SYM["RING"] + ((head + i) & mask): ord(c) for i, c in enumerate(text + "\r")}
    after = (head + len(text) + 1) & mask
    return memory | {SYM["RXHEAD"]: after & 0o377, SYM["RXHEAD"] + 1: after >> 8}


@pytest.mark.parametrize("text,head", [("1 2 + .", 0), ("", 511), ("x" * 255, 300),
                                       ("abc", 510), ("y" * 255, 0), ("z", 257)])
def test_the_load_and_the_deposits_write_what_the_interrupt_would(text, head):
    expected = interrupt_writes(text, head)
    image, after = ring_image(SYM, text, head)
    assert loaded(image) == expected and after == (head + len(text) + 1) & SYM["RING-MASK"]
    assert deposited(feed_commands(SYM, text, head)) == expected
