"""make soak-disk: is what FLUSH wrote on the disk image, whatever happens next?

Each cycle boots the FORTH on the same image, checks that it reads back what
the previous cycles flushed, writes new contents into some blocks, FLUSHes
(SAVE-BUFFERS every other cycle), then UPDATEs one more block without FLUSH
(through BUFFER: no disk operation follows the write-back) and kills the simulator with
SIGKILL at once (no DETACH, no exit: what a crash or a power cut leaves).
After each kill the whole image is compared with a model of what it must
hold:

  lost       a flushed block that does not hold what was flushed
  corrupted  any other block that differs from the model (the UPDATEd but
             unflushed block may hold its old or its new contents, nothing else)

Every 5th cycle instead kills the simulator a few host milliseconds after FLUSH
is typed, while it writes: each edited block may then be old or new, but whole,
and no other block may change.

    python -m harness.soak.disk_soak [CYCLES]     default 100; exit 1 on any loss

tests/disk/test_durability.py runs a short version. Contents change every
cycle: each edited block is filled with a character and its first cell holds
the cycle number, so a block left over from an earlier cycle is noticed.
"""
import os
import random
import signal
import sys
import tempfile
import time
from dataclasses import dataclass, field

from harness.blocks.blockfile import BLOCK_BYTES
from harness.blocks.disk import read_image
from harness.machine.build import fresh_disk
from harness.machine.machine import Machine

FIRST = 3000                # the blocks the soak edits: FIRST .. FIRST + SPAN - 1
SPAN = 8
EDITS_PER_CYCLE = 2
TORN_EVERY = 5              # every 5th cycle kills the simulator during FLUSH
TORN_DELAY = 0.004          # host seconds after FLUSH is typed, at most


def block_contents(cycle, block):
    """What cycle `cycle` writes into `block`: a fill character, the cycle number
    in the first cell (little-endian, as the PDP-11 stores it)."""
    fill = 33 + (cycle * 7 + block) % 94
    data = bytearray([fill]) * BLOCK_BYTES
    data[0:2] = (cycle & 0xFFFF).to_bytes(2, "little")
    return bytes(data)


def forth_edit(cycle, block, word="BLOCK"):
    """The FORTH line that gives `block` the contents block_contents(cycle, block).
    With BUFFER instead of BLOCK the block is not read first: no disk operation
    at all, so nothing after the write-back could push SIMH's buffer out."""
    fill = 33 + (cycle * 7 + block) % 94
    return f"{block} {word} DUP {BLOCK_BYTES} {fill} FILL {cycle} SWAP ! UPDATE"


def write_back_word(cycle):
    """FLUSH in odd cycles, SAVE-BUFFERS (which keeps the buffers) in even ones."""
    return "FLUSH" if cycle % 2 else "SAVE-BUFFERS"


def cycle_blocks(cycle):
    """(blocks to edit and FLUSH, block to UPDATE without FLUSH) in this cycle."""
    edited = [FIRST + (cycle * EDITS_PER_CYCLE + i) % SPAN for i in range(EDITS_PER_CYCLE)]
    pending = FIRST + (cycle * EDITS_PER_CYCLE + EDITS_PER_CYCLE) % SPAN
    return edited, pending


@dataclass
class Tally:
    cycles: int = 0
    flushed: int = 0          # blocks FLUSH confirmed (" ok") before the kill
    lost: list = field(default_factory=list)        # (cycle, block)
    corrupted: list = field(default_factory=list)   # (cycle, block)
    unconfirmed: int = 0      # blocks written but not confirmed when the kill came
    unconfirmed_kept: int = 0  # of which the new contents reached the disk
    seconds: float = 0.0


def compare(image, model, confirmed, unconfirmed, cycle, tally):
    """Check `image` (bytes) against `model` ({block: bytes}; every other block as
    in the base image `model[None]`). Blocks in `confirmed` must hold their model
    contents (else lost); a block of `unconfirmed` ({block: new bytes}) may hold
    its old or its new contents, whole; anything else is corrupted. The model
    follows what is found, so a fault is counted once."""
    base = model[None]
    expected = bytearray(base)
    for n, data in model.items():
        if n is not None:
            expected[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES] = data
    if expected == image:             # the usual case, checked at memory speed
        return
    for n in range(len(image) // BLOCK_BYTES):
        got = image[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES]
        if got == expected[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES]:
            continue
        if got == unconfirmed.get(n):
            tally.unconfirmed_kept += 1
        else:
            (tally.lost if n in confirmed else tally.corrupted).append((cycle, n))
        model[n] = got


def kill_now(machine):
    """SIGKILL the simulator: nothing of it runs after the FORTH's answer."""
    os.kill(machine.child.pid, signal.SIGKILL)
    machine.child.wait()
    machine.child.ptyproc.delayafterclose = 0      # it is dead: no grace period
    machine.child.close()


def torn_cycle(cycle):
    """Every TORN_EVERY-th cycle the kill comes while FLUSH is writing: it may
    leave each block old or new, never half of one, and touch nothing else."""
    return cycle % TORN_EVERY == 0


def one_cycle(image, cycle, model, tally):
    edited, pending = cycle_blocks(cycle)
    m = Machine(disk=image)
    try:
        for block in edited:             # the FORTH reads back the last flushed contents
            seen = int(m.send(f"{block} BLOCK @ U.").split()[0])
            if block in model and seen != int.from_bytes(model[block][0:2], "little"):
                tally.lost.append((cycle, block))
            m.send(forth_edit(cycle, block))
        if torn_cycle(cycle):
            m.child.send("FLUSH\r")
            time.sleep(random.Random(cycle).uniform(0, TORN_DELAY))
        else:
            m.send(write_back_word(cycle))
            m.send(forth_edit(cycle, pending, "BUFFER"))
        kill_now(m)
    finally:
        m.close()
    new = {block: block_contents(cycle, block) for block in edited}
    if torn_cycle(cycle):
        unconfirmed, confirmed = new, {}
    else:
        unconfirmed, confirmed = {pending: block_contents(cycle, pending)}, new
        model.update(confirmed)
    compare(read_image(image), model, confirmed, unconfirmed, cycle, tally)
    tally.cycles += 1
    tally.flushed += len(confirmed)
    tally.unconfirmed += len(unconfirmed)


def soak(image, cycles):
    """Run `cycles` cycles on `image` (changed in place); the Tally."""
    model = {None: read_image(image)}
    tally = Tally()
    start = time.perf_counter()
    for cycle in range(1, cycles + 1):
        one_cycle(image, cycle, model, tally)
    tally.seconds = time.perf_counter() - start
    return tally


def report(tally):
    return (f"{tally.cycles} cycles of edit -> FLUSH/SAVE-BUFFERS -> UPDATE -> kill -9 -> "
            f"reboot (every {TORN_EVERY}th: kill -9 during FLUSH): "
            f"{tally.flushed} flushed blocks, {len(tally.lost)} lost, "
            f"{len(tally.corrupted)} corrupted; of {tally.unconfirmed} writes not "
            f"confirmed at the kill, {tally.unconfirmed_kept} reached the disk; "
            f"{tally.seconds:.1f} s "
            f"({1000 * tally.seconds / max(tally.cycles, 1):.0f} ms per cycle)"
            + "".join(f"\n  lost: cycle {c} block {b}" for c, b in tally.lost)
            + "".join(f"\n  corrupted: cycle {c} block {b}" for c, b in tally.corrupted))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    cycles = int(argv[0]) if argv else 100
    with tempfile.TemporaryDirectory(prefix="soak-disk-") as tmp:
        image = fresh_disk(tmp, "soak.dsk")
        tally = soak(image, cycles)
    print(report(tally))
    return 1 if tally.lost or tally.corrupted else 0


if __name__ == "__main__":
    sys.exit(main())
