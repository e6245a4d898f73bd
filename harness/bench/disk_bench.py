"""make bench-disk: PDP-11 instructions spent by the RL02 driver and block buffers.

Counted as harness.bench.forth_bench counts: SIMH breakpoints on two CODE words around
the work print SHOW TIME, at priority 6 so the stock clock's interrupts stay out.
SIMH's RL model answers after a fixed number of instructions (STIME per cylinder
of seek, RTIME per transfer), so the figures are the driver's own cost, not the
mechanical latency of a real RL02 (which would add tens of milliseconds).

The write-through (pdp11-devices/simh/rl_durable.c: fflush and fsync after every block
written) costs no instruction, only host time: measured as the wall time of a
FORTH loop writing WRITES blocks one FLUSH each, minus the same loop without
UPDATE (no writes), per block; beside it, what one 1024-byte write plus fsync
costs Python on the same file system (the host's own price for durability)."""
import os
import sys
import tempfile
import time
from pathlib import Path

from harness.bench.forth_bench import count, start_counting
from harness.machine.build import RATE, ROOT
from harness.machine.machine import SIMULATOR, Machine, blank_disk

SETUP = r"""
: B-HIT QUIET 1 BLOCK DROP MARK 1 BLOCK DROP END-MARK LOUD ;
: B-TRACK QUIET EMPTY-BUFFERS 2 BLOCK DROP MARK 3 BLOCK DROP END-MARK LOUD ;
: B-STROKE QUIET EMPTY-BUFFERS 0 BLOCK DROP MARK 10239 BLOCK DROP END-MARK LOUD ;
: B-WRITE QUIET EMPTY-BUFFERS 4 BLOCK DROP UPDATE MARK FLUSH END-MARK LOUD ;
: B-LOAD QUIET 100 BLOCK DROP MARK 100 LOAD END-MARK LOUD ;
: B-EVAL QUIET 100 BLOCK 1024 PAD SWAP MOVE MARK PAD 1024 EVALUATE END-MARK LOUD ;
: WRITE-LOOP ( n -- ) 0 DO 3000 I + BUFFER DROP UPDATE FLUSH LOOP ;
: SAME-NO-WRITE ( n -- ) 0 DO 3000 I + BUFFER DROP FLUSH LOOP ;
"""
WRITES = 200

# block 100: 16 lines of 8 words each = 128 words to parse and execute
LOAD_BLOCK = ("1 DROP " * 8).ljust(64) * 16


def main():
    with tempfile.TemporaryDirectory() as tmp:
        disk = blank_disk(Path(tmp) / "bench.dsk")
        with open(disk, "r+b") as f:
            f.seek(100 * 1024)
            f.write(LOAD_BLOCK.encode("ascii"))
        with Machine(disk=disk, timeout=120) as m:
            empty = start_counting(m, SETUP)
            rows = [(name, count(m, word) - empty) for name, word in [
                ("BLOCK, already in a buffer", "B-HIT"),
                ("BLOCK, read from the same track", "B-TRACK"),
                ("BLOCK, read after a 511-cylinder seek", "B-STROKE"),
                ("FLUSH of one UPDATEd block (write)", "B-WRITE"),
                ("LOAD of a block of 128 words (1 DROP x 64)", "B-LOAD"),
                ("EVALUATE of the same text from memory", "B-EVAL"),
            ]]
            write_us = host_us_per_write(m)
        fsync_us = python_fsync_us(disk)
    print(f"RL02 driver and block buffers on {os.path.relpath(SIMULATOR, ROOT)}, "
          f"simulated seconds at {RATE} instructions/s")
    print(f"{'operation':45s} {'instructions':>14s} {'ms':>9s}")
    for name, n in rows:
        print(f"{name:45s} {n:14d} {1000 * n / RATE:9.2f}")
    flush = dict(rows)["FLUSH of one UPDATEd block (write)"]
    print(f"\nFLUSH write-through (pdp11-devices/simh/rl_durable.c), per block written:\n"
          f"  PDP-11 instructions {flush:10d}   (the write-through adds none)\n"
          f"  host microseconds   {write_us:10.1f}   (wall time of {WRITES} FLUSHed "
          "writes minus the same loop without them; fflush + fsync included)\n"
          f"  host microseconds   {fsync_us:10.1f}   (reference: Python writing 1024 "
          "bytes and fsync()ing, same file system)")
    if any(n <= 0 for _, n in rows):
        print("a count is not positive: the breakpoints did not fire", file=sys.stderr)
        sys.exit(1)


def _wall(m, line):
    start = time.perf_counter()
    m.send(line)
    return time.perf_counter() - start


def host_us_per_write(m, tries=3):
    """Host microseconds per block written by FLUSH (best of `tries`)."""
    best = min(_wall(m, f"{WRITES} WRITE-LOOP") - _wall(m, f"{WRITES} SAME-NO-WRITE")
               for _ in range(tries))
    return 1e6 * best / WRITES


def python_fsync_us(image, n=WRITES):
    """Microseconds for one 1024-byte write and fsync into `image`."""
    with open(image, "r+b") as f:
        start = time.perf_counter()
        for i in range(n):
            f.seek((3000 + i) * 1024)
            f.write(b" " * 1024)
            f.flush()
            os.fsync(f.fileno())
        return 1e6 * (time.perf_counter() - start) / n


if __name__ == "__main__":
    main()
