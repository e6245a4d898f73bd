"""The ASN's cost on the 11/23 (blocks 1070-1078, docs/learning.md): one
learning step's computation, Think below (read the counters, the 18 fields,
the payoff, Learn's 72 weight changes, Choose's 72 products and 4 noises,
the copy of the pattern: Step without its printing, Act.Move and Settle),
by instruction count and priced on the KDF11-A (harness/analysis/timing.py,
the tables of shared/kdf11-timing.md), with no servo installed so that no
interrupt falls inside it.

    python -m harness.bench.asn_bench          (make bench-asn)
"""
import sys
import tempfile

from harness.analysis import timing
from harness.analysis.servo_timing import setup_script
from harness.machine.build import RATE, fresh_disk
from harness.machine.kernel_layout import read_kernel_map
from harness.machine.robot import Robot
from harness.machine.scripted_machine import feed_commands
REPEAT = 100
LINES = ["1000 LOAD 1070 LOAD",
         ": Mark ( -- ) ;",
         ": Think ( -- ) 0 Read.Counter 1 Read.Counter 2DUP Sense 2DUP Payoff "
         "Reinforce At.Goal? DROP Choose Act ! X.Now X.Was #In 2* CMOVE ;",
         f": Bench ( -- ) 1 Steps !  {REPEAT} 0 DO Think Mark LOOP ;",
         "Reset.Net 1800 2000 Sense 1 Steps !"]


def counted(disk):
    """(Think's and Mark's code addresses, instructions per Think by the
    simulated clock over REPEAT of them)."""
    with Robot(disk=disk, timeout=120) as r:
        for line in LINES:
            r.send(line)
        think, mark = (int(v) for v in r.send("' Think U. ' Mark U.").split())
        t0 = r.time()
        r.send("Bench")
        t1 = r.time()
        r.send(": Empty ( -- ) 1 Steps ! 100 0 DO Mark Mark LOOP ;")
        e0 = r.time()
        r.send("Empty")
        e1 = r.time()
    per = ((t1 - t0) - (e1 - e0)) * RATE / REPEAT
    return think, mark, per


def main():
    with tempfile.TemporaryDirectory(prefix="asn-bench-") as tmp:
        think, mark, per = counted(fresh_disk(tmp))
        disk = fresh_disk(tmp)
        # stopped at QUERY after the lines, Bench typed ahead into the ring
        sym = read_kernel_map()
        setup = setup_script(disk, LINES) + "\n".join(
            [f"deposit {sym['RXTAIL']:o} 0"] + feed_commands(sym, "Bench", 0)) + "\n"
        report = timing.measure(setup, entry=think, end=mark,
                                instructions=round(per * REPEAT * 1.2) + 50_000)
    n = report.count
    instructions = report.total_instructions / max(n, 1)
    print(f"  ASN learning step (Think: sense, payoff, learn, choose), {n} executions: "
          f"{instructions:.0f} instructions each (by the simulated clock: {per:.0f} with the "
          f"loop around it), {report.mean_us / 1000:.2f} ms each on a KDF11-A "
          f"= {instructions / RATE * 1000:.2f} ms at {RATE} instructions/s")
    return 0 if n else 1


if __name__ == "__main__":
    sys.exit(main())
