"""make bench (devices): how fast the host runs the FORTH, in PDP-11 instructions
per host second, for the builds and the two ways a scripted run stops at the prompt.

The workload: the BYTE Sieve, 50 iterations (about 45 M instructions), run as
one scripted line (harness/machine/scripted_machine.py) after
1000 LOAD, so the clock ticks and the servo idles as in every robot run. The line's
instruction count comes from SHOW CLK's time (instructions / RATE); its host time
is the wall time of that one SIMH round trip, best of ROUNDS with the variants
taking turns (the host is shared: noise only slows runs). The ratios are also
taken round by round and their median printed with their spread: on a shared
host the best-of figures of two variants can come from different moments (the
guided/plain ratio of the best-of figures read 1.16 to 1.39 on one afternoon),
and a round's two runs are seconds apart.

Variants:
  cue         build/pdp11-plain, the CUE device stops at the prompt (what runs today)
  breakpoint  build/pdp11-plain, a SIMH breakpoint at the same place (what scripted
              runs did before: SIMH tests every instruction's address)
  guided      build/pdp11-guided (mk/pgo.mk), the CUE device"""
import re
import tempfile
import time

from harness.bench.paired import per_round
from harness.machine.build import BUILD, fresh_disk
from harness.machine.scripted_machine import ScriptedMachine

ROUNDS = 9
SIEVE = [
    "8190 CONSTANT SIZE  CREATE FLAGS SIZE ALLOT",
    ": PRIMES ( -- n ) FLAGS SIZE 1 FILL  0 SIZE 0 DO FLAGS I + C@ IF I 2* 3 + DUP I + "
    "BEGIN DUP SIZE < WHILE 0 OVER FLAGS + C! OVER + REPEAT 2DROP 1+ THEN LOOP ;",
    ": SIEVE ( -- n ) 0 50 0 DO DROP PRIMES LOOP ;",
]
PLAIN, GUIDED = BUILD / "pdp11-plain", BUILD / "pdp11-guided"
VARIANTS = {"cue": (PLAIN, False), "breakpoint": (PLAIN, True), "guided": (GUIDED, False)}


def clock_time(m):
    return float(re.search(r"time=([\d.]+)s", m.simh("show clk")).group(1))


def sieve_run(simulator, breakpoint):
    """(instructions, host seconds) of one `SIEVE .` line."""
    with tempfile.TemporaryDirectory() as tmp:
        with ScriptedMachine(fresh_disk(tmp).name, cwd=tmp, simulator=simulator,
                             cue_breakpoint=breakpoint) as m:
            for line in ["1000 LOAD"] + SIEVE:
                m.line(line)
            before = clock_time(m)
            start = time.perf_counter()
            answer = m.line("SIEVE .", limit=600)
            wall = time.perf_counter() - start
            if "1899" not in answer.output:
                raise SystemExit(f"bench: the Sieve went wrong on {simulator}: {answer.output}")
            return round((clock_time(m) - before) * m.rate), wall


def rates(rounds=ROUNDS):
    """(instructions, variant -> [M instructions per host second, a round each])."""
    runs = {name: [] for name in VARIANTS}
    for _ in range(rounds):
        for name, (simulator, breakpoint) in VARIANTS.items():
            n, wall = sieve_run(simulator, breakpoint)
            runs[name].append(n / wall / 1e6)
    return n, runs


def ratio(runs, a, b):
    """a against b, best against best, and round by round: 'best 1.21x; per round
    median 1.18x (1.02-1.40)'."""
    median, low, high = per_round(runs[a], runs[b])
    return (f"best {max(runs[a]) / max(runs[b]):.2f}x; per round median "
            f"{median:.2f}x ({low:.2f}-{high:.2f})")


def report():
    n, runs = rates()
    best = {name: max(rates_) for name, rates_ in runs.items()}
    print(f"FORTH host speed: the Sieve ({n:,} instructions) after 1000 LOAD, best of "
          f"{ROUNDS}, taking turns (M PDP-11 instructions per host second)")
    print(f"  build/pdp11-plain, stop by the CUE device : {best['cue']:8.1f}")
    print(f"  build/pdp11-plain, stop by a breakpoint   : {best['breakpoint']:8.1f}  "
          f"(before issue 19; cue/breakpoint {ratio(runs, 'cue', 'breakpoint')})")
    print(f"  build/pdp11-guided (profile-guided)       : {best['guided']:8.1f}  "
          f"(guided/plain {ratio(runs, 'guided', 'cue')})")
    print("  build/pdp11 is guided only with make PGO=1: it would pay at 1.3x, the "
          "round-by-round median")
