"""make bench-forth: PDP-11 instructions executed by FORTH benchmarks.

SIMH counts instructions (SHOW TIME at a stop). CODE words MARK and END-MARK
(just NEXT) carry simulator breakpoints whose actions print the time and
continue; each benchmark is a colon definition `MARK <work> END-MARK`, so the
difference is the work alone (plus MARK's own NEXT, measured by an empty pair
and subtracted). Each figure is printed beside the one it replaced: the kernel
before issue 19's hashed dictionary search (main at 529275f: 4 chains per word
list by name length, the search order walked in FORTH), measured the same way. Each runs at processor priority 6: the stock 11/23's line clock
cannot be disabled and ticks at a host-calibrated rate, so its interrupts are held
off to keep the counts exact. Simulated seconds use the 11/23's typical 300 000
instructions per second (docs/design.md section 2)."""
import re
import sys
import tempfile

from harness.bench.protection_cost import cost
from harness.machine.build import RATE, ROOT, fresh_disk
from harness.machine.machine import OK, SIMULATOR, Machine


# the counting words: breakpoints go on MARK and END-MARK; QUIET/LOUD hold the
# clock's interrupts off; B-EMPTY measures the pair itself
MARK_WORDS = r"""
CODE MARK NEXT, END-CODE
CODE END-MARK NEXT, END-CODE
CODE QUIET 300O # MTPS, NEXT, END-CODE
CODE LOUD 0 # MTPS, NEXT, END-CODE
: B-EMPTY QUIET MARK END-MARK LOUD ;
"""

SETUP = r"""
CODE NOP NEXT, END-CODE
: NOOP ;
: INNER END-MARK ;
: INNER-EXIT MARK ;
8190 CONSTANT SIZE
CREATE FLAGS SIZE ALLOT
: PRIMES ( -- n ) FLAGS SIZE 1 FILL  0 SIZE 0 DO FLAGS I + C@ IF
  I 2* 3 + DUP I + BEGIN DUP SIZE < WHILE 0 OVER FLAGS + C! OVER + REPEAT
  2DROP 1+ THEN LOOP ;
: SIEVE ( -- n ) 0 10 0 DO DROP PRIMES LOOP ;
: EMPTY-LOOP 10000 0 DO LOOP ;
: FIB ( n -- fib ) DUP 2 < IF EXIT THEN 1- DUP RECURSE SWAP 1- RECURSE + ;
: B-NEXT QUIET MARK NOP END-MARK LOUD ;
: B-DOCOL QUIET MARK INNER LOUD ;
: B-EXIT QUIET INNER-EXIT END-MARK LOUD ;
: B-CALL QUIET MARK NOOP END-MARK LOUD ;
: B-SIEVE QUIET MARK SIEVE END-MARK LOUD ;
: B-LOOP QUIET MARK EMPTY-LOOP END-MARK LOUD ;
: B-FIB QUIET MARK 20 FIB END-MARK LOUD ;
CREATE TEXT 448 ALLOT
: TEXT! ( -- ) 64 0 DO S" 1 DROP " TEXT I 7 * + SWAP MOVE LOOP ;
: B-INTERPRET QUIET TEXT! MARK TEXT 448 EVALUATE END-MARK LOUD ;
: BUS-ERROR 160000O @ ;
: B-TRAP QUIET MARK ['] BUS-ERROR CATCH DROP END-MARK LOUD ;
: B-LOAD QUIET MARK 1000 LOAD END-MARK LOUD ;
"""

# (label, word, instructions before issue 19's hashed dictionary search)
BENCHMARKS = [
    ("BYTE Sieve, 10 iterations of 8190 flags", "B-SIEVE", 9245725),
    ("10 000 empty DO LOOP passes", "B-LOOP", 60023),
    ("recursive Fibonacci of 20", "B-FIB", 689562),
    ("outer interpreter: EVALUATE of 64 x '1 DROP'", "B-INTERPRET", 374960),
    ("bus error trapped and caught by CATCH", "B-TRAP", 10123),
    ("1000 LOAD (the paper's blocks 1000-1012)", "B-LOAD", 2075402),
]
WORDS_INTERPRETED = 128
# the dictionary's free bytes (UNUSED) at boot and after 1000 LOAD: the 16 KB floor
# at boot (issue 12), and the kernel before issue 19's 32 chains (8 chains, 16 420 and
# 14 392 bytes)
FREE_FLOOR = 16384
FREE_BEFORE = (16420, 14392)

TIME = re.compile(r"Time:\s+(\d+)")


def count(m, word):
    """Instructions between the two MARK stops while `word` runs; the
    breakpoint's actions print SHOW TIME and continue."""
    m.child.send(word + "\r")
    times = []
    for _ in range(2):
        m.child.expect(TIME)
        times.append(int(m.child.match.group(1)))
    m.child.expect(OK)
    return times[1] - times[0]


def start_counting(m, setup):
    """Define the counting words and `setup` (FORTH lines), put the breakpoints
    (with actions) on MARK and END-MARK, resume; the cost of an empty pair."""
    for line in (MARK_WORDS + setup).strip().splitlines():
        m.send(line)
    m.send("OCTAL")
    marks = [m.send(f"' {w} U.").split()[0] for w in ("MARK", "END-MARK")]
    m.send("DECIMAL")
    m.to_sim()
    for mark in marks:  # two words: SIMH does not stop twice in a row at one PC
        m.simh(f"break {mark};show time;cont")
    m.cont()
    return count(m, "B-EMPTY")


def free_bytes():
    """UNUSED at boot (the banner's figure) and after 1000 LOAD, on a fresh machine."""
    with tempfile.TemporaryDirectory() as tmp, \
            Machine(disk=fresh_disk(tmp), timeout=120) as m:
        boot = int(m.send("UNUSED U.").split()[0])
        m.send("1000 LOAD")
        return boot, int(m.send("UNUSED U.").split()[0])


def main():
    free = free_bytes()
    with tempfile.TemporaryDirectory() as tmp, \
            Machine(disk=fresh_disk(tmp), timeout=120) as m:
        empty = start_counting(m, SETUP)
        rows = [(name, count(m, word) - empty, before)
                for name, word, before in BENCHMARKS]
        nxt = count(m, "B-NEXT") - empty
        docol = count(m, "B-DOCOL") - empty
        exit_ = count(m, "B-EXIT") - empty
        call = count(m, "B-CALL") - empty
        m.to_sim()
        m.simh("nobreak all")
        m.cont()
        primes = m.send("SIEVE .").split()[0]
        fib = m.send("20 FIB .").split()[0]
    print(f"FORTH benchmarks on {SIMULATOR.relative_to(ROOT)}, simulated seconds at "
          f"{RATE} instructions/s")
    print(f"{'benchmark':45s} {'instructions':>14s} {'seconds':>9s} {'before':>10s}")
    for name, n, before in rows:
        print(f"{name:45s} {n:14d} {n / RATE:9.3f} {before:10d}")
    print(f"  (sieve found {primes} primes per iteration; fib(20) = {fib})")
    words = rows[3]
    print(f"  (the interpreter: {words[1] // WORDS_INTERPRETED} instructions per word, "
          f"number or name, including the dictionary search; "
          f"{words[2] // WORDS_INTERPRETED} before)")
    print(f"dictionary free: {free[0]} bytes at boot (floor {FREE_FLOOR}), {free[1]} after "
          f"1000 LOAD; {FREE_BEFORE[0]} and {FREE_BEFORE[1]} with 8 chains")
    print(f"instructions per NEXT {nxt}, DOCOL {docol}, EXIT {exit_}, "
          f"call of an empty colon word {call}")
    print("anchors: polyFORTH Sieve 75 s on an 11/03, 12.5 s on an 11/60; "
          "fig-FORTH's NEXT is 2 instructions")
    print("what issue 16's checks cost (harness/bench/protection_cost.py):")
    for key, (_, n, _) in zip(["sieve", "loop", "fib", "interpret"], rows):
        print(cost(key, n))
    if primes != "1899" or fib != "6765":
        print("benchmark results wrong", file=sys.stderr)
        sys.exit(1)
    if free[0] < FREE_FLOOR:
        print(f"the kernel leaves {free[0]} bytes at boot, below the floor of {FREE_FLOOR}",
              file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
