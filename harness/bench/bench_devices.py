"""make bench (devices): host speed of build/pdp11 against SIMH's stock build.

One fixed PDP-11 program: a compute loop (ADD, MOV, SOB) interrupted 60 times a
simulated second by the line clock, whose handler does what the 1983 servo
does with the I/O: per axis, select the counter on the DRV11, read it, write a
velocity code to the AAV11-A: +-100 codes towards counter 0, so every axis
keeps swinging about its start and the plant never rests. Variants:
  plant active  build/pdp11-plain, the handler's I/O goes to the DRV11 and AAV11-A
  plant idle    build/pdp11-plain, the same instructions on memory (plant untouched)
  guided        build/pdp11-guided (mk/pgo.mk), plant active
  stock         build/pdp11-stock, the idle program (the stock 11/23 has no
                LKS register and forces clock interrupts on; the handler runs
                at its wall-calibrated rate)
Each runs STEPS instructions (SIMH STEP) ROUNDS times, the variants taking
turns; the best wall time counts (the host is shared: noise only slows runs).
Prints instructions per host second, the ratios to stock (goal >= 0.9) and the
real-time factor (simulated seconds per wall second at RATE)."""
import sys
import time

from harness.analysis.pdp11prog import Program, check_listing
from harness.bench import forth_host_speed
from harness.machine import simh
from harness.machine.build import PDP11_STOCK, RATE
from harness.machine.plant_rows import AXES

STEPS = 100_000_000                                       # 333 simulated seconds
ROUNDS = 5
SCRATCH = 0o3000
LKS, DRV_CSR, DRV_OUT, DRV_IN, DAC0 = 0o177546, 0o167770, 0o167772, 0o167774, 0o170440


def program(io, clock=True):
    """io=True: the handler talks to the devices; False: to memory at 3000..
    clock=False: no LKS write (stock SIMH has no LKS on an 11/23)."""
    csr, inbuf, dac = (DRV_CSR, DRV_IN, DAC0) if io else (SCRATCH, SCRATCH + 2, SCRATCH + 4)
    p = Program()
    p.mov_imm(0o17, DRV_OUT if io else SCRATCH + 0o22)    # counters run
    p.mov_imm(0o100, LKS if clock else SCRATCH + 0o20)    # clock interrupts on
    outer = p.here
    p.mov_imm_reg(0o1000, 0)
    inner = p.here
    p.op("ADD R0,R2", 0o060002)
    p.op("MOV R2,R3", 0o010203)
    p.op(f"SOB R0,{inner:o}", 0o077000 | ((p.here + 2 - inner) // 2))
    p.op(f"BR {outer:o}", 0o000400 | ((outer - p.here - 2) // 2 & 0o377))

    def servo(h):
        for axis in range(len(AXES)):
            h.mov_imm(axis, csr)
            h.op(f"MOV @#{inbuf:o},R1", 0o013701, inbuf)
            h.op("MOV #3634,R2", 0o012702, 0o3634)        # above 0: -100 codes
            h.op("TST R1", 0o005701)
            h.op(f"BPL {h.here + 6:o}", 0o100002)
            h.op("MOV #4144,R2", 0o012702, 0o4144)        # below 0: +100 codes
            target = dac + (2 * axis if io else 0)
            h.op(f"MOV R2,@#{target:o}", 0o010237, target)
    p.handler(0o100, 0o1400, servo)
    return p


def run_once(prog, simulator, expect):
    """Wall seconds for one run of STEPS instructions; `expect`: text it must print."""
    script = prog.script(start=False) + f"step {STEPS}\nshow aav11\n"
    t0 = time.perf_counter()
    out = simh.run(script, simulator=simulator)
    dt = time.perf_counter() - t0
    if "Step expired" not in out or expect not in out:
        sys.exit(f"bench: the program stopped early on {simulator.name}:\n{out}")
    return dt


def best_rates(variants, rounds=ROUNDS):
    """Instructions per wall second, best of `rounds`; the variants take turns so
    that a busy spell of the host hits all of them alike."""
    best = [None] * len(variants)
    for _ in range(rounds):
        for i, (prog, simulator, expect) in enumerate(variants):
            dt = run_once(prog, simulator, expect)
            best[i] = dt if best[i] is None or dt < best[i] else best[i]
    return [STEPS / b for b in best]


def main():
    for sim in (forth_host_speed.PLAIN, forth_host_speed.GUIDED, PDP11_STOCK):
        if not sim.exists():
            sys.exit(f"bench: {sim} missing: run make")
    active, idle, stock = program(io=True), program(io=False), program(io=False, clock=False)
    for prog in (active, idle, stock):
        bad = check_listing(prog)
        if bad:
            sys.exit(f"bench: hand-assembled words disagree with SIMH: {bad}")
    ips_active, ips_idle, ips_stock, ips_guided = best_rates([
        (active, forth_host_speed.PLAIN, "AAV11, X="), (idle, forth_host_speed.PLAIN, ""),
        (stock, PDP11_STOCK, ""), (active, forth_host_speed.GUIDED, "AAV11, X=")])
    print(f"devices benchmark: {STEPS:,} instructions per run, best of {ROUNDS}, taking turns")
    print(f"  build/pdp11-plain, clock + plant active : {ips_active / 1e6:8.2f} M instructions/s")
    print(f"  build/pdp11-plain, clock, plant idle    : {ips_idle / 1e6:8.2f} M instructions/s")
    print(f"  build/pdp11-stock                 : {ips_stock / 1e6:8.2f} M instructions/s")
    print(f"  ratio active/stock {ips_active / ips_stock:.3f}, idle/stock "
          f"{ips_idle / ips_stock:.3f} (goal >= 0.9)")
    print(f"  real-time factor at {RATE} instructions/s: active {ips_active / RATE:.0f}x, "
          f"idle {ips_idle / RATE:.0f}x (simulated seconds per wall second)")
    print(f"  build/pdp11-guided, clock + plant : {ips_guided / 1e6:8.2f} M instructions/s "
          f"(guided/plain {ips_guided / ips_active:.3f}, guided/stock {ips_guided / ips_stock:.3f})")
    forth_host_speed.report()


if __name__ == "__main__":
    main()
