"""Two simulators on one image, the fuzz's last case (issue 16, item 8).

While the fuzz's machine has its disk image attached, seeded rounds each have
it FLUSH a new fill into one of a few blocks, then try a second simulator on
the same image:
  read-write  must be refused, naming the holder (pdp11-devices/simh/rl_one_writer.c);
  read-only   must boot, read what the first FLUSHed, and answer its own
              UPDATE FLUSH with an error (the drive is write-locked); its QUIT
              is then refused and QUIT -F leaves without the block.
At the end the image must hold every fill the first machine FLUSHed, and no
block the second ones tried to write. Each failure is one line.
"""
import random

from harness.blocks.blockfile import BLOCK_BYTES
from harness.machine.scripted_machine import ScriptError, ScriptedMachine

FIRST = 3000                # blocks the first machine writes: FIRST .. FIRST + SPAN - 1
SPAN = 4
INTRUDER = FIRST + SPAN     # the block the read-only ones try to write


def fill_line(block, fill):
    return f"{block} BLOCK {BLOCK_BYTES} {fill} FILL UPDATE FLUSH"


def check(machine, workdir, disk, rounds, seed):
    """Run the rounds against `machine` (a ScriptedMachine on workdir/disk);
    the list of failures."""
    rng, written, failures = random.Random(seed), {}, []
    for n in range(1, rounds + 1):
        block, fill = FIRST + rng.randrange(SPAN), 33 + rng.randrange(94)
        if not machine.line(fill_line(block, fill)).ok:
            failures.append(f"round {n}: the first machine's FLUSH of block {block} failed")
            continue
        written[block] = fill
        if rng.random() < 0.5:
            failures += _second_writer(workdir, disk, n)
        else:
            failures += _reader(workdir, disk, n, block, fill, 33 + rng.randrange(94))
    image = (workdir / disk).read_bytes()
    for block, fill in sorted(written.items()):
        if image[block * BLOCK_BYTES:(block + 1) * BLOCK_BYTES] != bytes([fill]) * BLOCK_BYTES:
            failures.append(f"block {block} does not hold the fill {fill} FLUSHed last")
    if image[INTRUDER * BLOCK_BYTES:(INTRUDER + 1) * BLOCK_BYTES].strip(b" "):
        failures.append(f"block {INTRUDER}, written only by read-only simulators, changed")
    return failures


def _second_writer(workdir, disk, n):
    try:
        ScriptedMachine(disk, cwd=workdir).close()
    except ScriptError as refused:
        return [] if "in use by pid" in str(refused) else [f"round {n}: {refused}"]
    return [f"round {n}: a second read-write simulator was admitted"]


def _reader(workdir, disk, n, block, fill, other):
    with ScriptedMachine(disk, cwd=workdir, read_only=True) as reader:
        seen = reader.line(f"{block} BLOCK C@ .").output
        tried = reader.line(fill_line(INTRUDER, other))
    failures = []
    if f" {fill} " not in seen:
        failures.append(f"round {n}: the read-only simulator read {seen!r}, not {fill}")
    if "write-locked" not in tried.output or not tried.error:
        failures.append(f"round {n}: the read-only simulator's FLUSH was not an error: "
                        f"{tried.output!r}")
    return failures
