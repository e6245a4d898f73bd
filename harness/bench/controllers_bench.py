"""make bench (controllers): the five machines of issue 21 at full speed, and what
the lock-step costs against the same five simulators running free.

One fixed workload per machine (machine code deposited by SIMH, no FORTH, so
nothing but the simulators and the lock-step is measured): a compute loop that
writes its D/A channel 0 every 256 passes (an event for the plant each time, as
a servo's output would be), run for SECONDS simulated seconds (STEP, at the
default 300000 instructions per simulated second) on the 11/23 and the four
LSI-11/03s at once:
  lock-step   the five joined to build/lockstep-coordinator (1 ms quanta: one
              boundary exchange per machine per simulated ms)
  free        the five as independent simulators, no coordinator, the same steps
Each variant runs ROUNDS times, taking turns; the median wall time counts (the
host is shared). Printed: the aggregate instruction rate of the five (5 x steps
/ wall), the overhead of the lock-step, its cost per boundary, and the same with
0.1 ms quanta (what a shorter quantum would cost). Then build/barrier-bench: one
boundary with nothing simulated, the design built (a coordinator process, Unix
sockets) against a shared-memory futex barrier (the other design issue 21
allowed; docs/controllers.md says why the coordinator). Instruction counts are
exact; wall times depend on the host and its load.

python -m harness.bench.controllers_bench [--one lockstep|free] [--quanta N]
  --one runs a single session of one variant (for timing from outside)."""
import argparse
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from harness.controllers.coordinator import CONTROLLERS, MEMBERS, Coordinator, member_settings
from harness.machine import simh
from harness.machine.build import BUILD, CPU_1103, MACHINE_INI, PDP11, RATE

SECONDS = 10
ROUNDS = 3
BARRIER_ROUNDS = 20000
DAC0 = 0o170440
# 1$: INC R0 ; MOV R0,R1 ; BIC #177400,R1 ; BNE 1$ ; MOV R0,@#170440 ; BR 1$
LOOP = [0o005200, 0o010001, 0o042701, 0o177400, 0o001373, 0o010037, DAC0, 0o000770]


def script(member, socket):
    settings = (member_settings(member, socket) if socket else
                (CPU_1103 if member in CONTROLLERS else ()))
    return (f"do {MACHINE_INI}\n" + "".join(f"{c}\n" for c in settings)
            + simh.deposit(0o1000, LOOP) + "deposit pc 1000\n"
            + f"step {SECONDS * RATE}\nquit\n")


def session(lockstep, quanta=1000):
    """One run of the five; its wall seconds."""
    with tempfile.TemporaryDirectory(prefix="bench-controllers-") as tmp:
        coordinator = Coordinator(tmp, quanta=quanta) if lockstep else None
        try:
            socket = coordinator.socket if coordinator else None
            paths = []
            for m in MEMBERS:
                path = Path(tmp) / f"{m}.ini"
                path.write_text(script(m, socket))
                paths.append(path)
            start = time.monotonic()
            procs = [subprocess.Popen([str(PDP11), str(p)], stdin=subprocess.DEVNULL,
                                      stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
                     for p in paths]
            for p in procs:
                p.wait()
            wall = time.monotonic() - start
        finally:
            if coordinator:
                coordinator.stop()
                coordinator.__exit__()
    return wall


def measure():
    variants = {"lock-step, 1 ms quanta": (True, 1000), "free": (False, 1000),
                "lock-step, 0.1 ms quanta": (True, 10000)}
    walls = {name: [] for name in variants}
    for _ in range(ROUNDS):
        for name, (lockstep, quanta) in variants.items():
            walls[name].append(session(lockstep, quanta))
    return {name: statistics.median(w) for name, w in walls.items()}


def report(walls):
    instructions = len(MEMBERS) * SECONDS * RATE
    free = walls["free"]
    print(f"five machines (the 11/23 and four 11/03s), {SECONDS} simulated s each "
          f"({instructions:,} instructions in all), median of {ROUNDS} (wall times on a "
          "shared host):")
    for name, wall in walls.items():
        print(f"  {name:26} {wall:6.2f} s wall  {instructions / wall / 1e6:6.1f} M "
              f"instructions/s aggregate  {SECONDS / wall:6.1f}x real time")
    for name, quanta in (("lock-step, 1 ms quanta", 1000), ("lock-step, 0.1 ms quanta", 10000)):
        boundaries = SECONDS * quanta
        extra = walls[name] - free
        print(f"  {name}: overhead {100 * extra / free:+.0f} % against five free-running "
              f"simulators, {1e6 * extra / boundaries:.1f} us wall per boundary "
              f"({boundaries:,} boundaries)")


def barrier_report():
    runs = [dict(line.split() for line in subprocess.run(
        [str(BUILD / "barrier-bench"), str(BARRIER_ROUNDS)], capture_output=True, text=True,
        check=True).stdout.splitlines()) for _ in range(ROUNDS)]
    star = statistics.median(float(r["star"]) for r in runs)
    futex = statistics.median(float(r["futex"]) for r in runs)
    print(f"one boundary of five processes, nothing simulated ({BARRIER_ROUNDS:,} rounds, "
          f"median of {ROUNDS}): coordinator over Unix sockets (built) {star:.1f} us, "
          f"shared-memory futex barrier {futex:.1f} us")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--one", choices=("lockstep", "free"))
    parser.add_argument("--quanta", type=int, default=1000)
    args = parser.parse_args(argv)
    if args.one:
        print(f"{session(args.one == 'lockstep', args.quanta):.3f} s wall")
        return 0
    report(measure())
    barrier_report()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
