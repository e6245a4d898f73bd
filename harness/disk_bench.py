"""make bench-disk: PDP-11 instructions spent by the RL02 driver and block buffers.

Counted as harness.forth_bench counts: SIMH breakpoints on two CODE words around
the work print SHOW TIME, at priority 6 so the stock clock's interrupts stay out.
SIMH's RL model answers after a fixed number of instructions (STIME per cylinder
of seek, RTIME per transfer), so the figures are the driver's own cost, not the
mechanical latency of a real RL02 (which would add tens of milliseconds)."""
import sys
import tempfile
from pathlib import Path

from harness.forth_bench import RATE, count, start_counting
from harness.machine import ROOT, SIMULATOR, Machine, blank_disk

SETUP = r"""
: B-HIT QUIET 1 BLOCK DROP MARK 1 BLOCK DROP END-MARK LOUD ;
: B-TRACK QUIET EMPTY-BUFFERS 2 BLOCK DROP MARK 3 BLOCK DROP END-MARK LOUD ;
: B-STROKE QUIET EMPTY-BUFFERS 0 BLOCK DROP MARK 10239 BLOCK DROP END-MARK LOUD ;
: B-WRITE QUIET EMPTY-BUFFERS 4 BLOCK DROP UPDATE MARK FLUSH END-MARK LOUD ;
: B-LOAD QUIET 100 BLOCK DROP MARK 100 LOAD END-MARK LOUD ;
: B-EVAL QUIET 100 BLOCK 1024 PAD SWAP MOVE MARK PAD 1024 EVALUATE END-MARK LOUD ;
"""

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
    print(f"RL02 driver and block buffers on {SIMULATOR.relative_to(ROOT)}, "
          f"simulated seconds at {RATE} instructions/s")
    print(f"{'operation':45s} {'instructions':>14s} {'ms':>9s}")
    for name, n in rows:
        print(f"{name:45s} {n:14d} {1000 * n / RATE:9.2f}")
    if any(n <= 0 for _, n in rows):
        print("a count is not positive: the breakpoints did not fire", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
