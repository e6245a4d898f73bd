"""The PDP-11 programs the device tests run (see pdp11prog.py for conventions),
and reading their results back."""
from harness.analysis.pdp11prog import Program, RESULTS
from harness.machine import simh

LKS = 0o177546
DRV_CSR, DRV_OUT, DRV_IN = 0o167770, 0o167772, 0o167774
DAC = [0o170440, 0o170442, 0o170444, 0o170446]
R = [RESULTS + 2 * i for i in range(16)]


def results(output, count, base=RESULTS):
    """The `count` result words at 2000.. as examined after the run."""
    ex = simh.examined(output)
    return [ex[f"{base + 2 * i:o}"] for i in range(count)]


def examine_results(count, base=RESULTS):
    return "".join(f"examine {base + 2 * i:o}\n" for i in range(count))


def lks_bits():
    """Write patterns to LKS (word and bytes), read back after each; RESET at the end."""
    p = Program()
    p.mov_imm(0o177777, LKS).mov_abs(LKS, R[0])       # 100: IE only (MON 0 before a tick)
    p.clr_abs(LKS).mov_abs(LKS, R[1])                  # 0
    p.movb_imm(0o377, LKS + 1).mov_abs(LKS, R[2])      # high byte: nothing there
    p.movb_imm(0o100, LKS).mov_abs(LKS, R[3])          # low byte sets IE
    p.reset().mov_abs(LKS, R[4])                       # bus INIT clears IE
    p.delay(8000)                                      # past the first tick (5000)
    p.mov_abs(LKS, R[5])                               # 200: MON set by the tick
    p.mov_imm(0o200, LKS).mov_abs(LKS, R[6])           # writing 1 to MON keeps it
    p.mov_imm(0o100, LKS).mov_abs(LKS, R[7])           # writing 0 clears it, IE set
    p.reset().mov_abs(LKS, R[8])                       # INIT clears MON and IE
    return p.halt()


def clock_counter(enable=True):
    """Count clock interrupts at 2000 (handler at vector 100), spin forever."""
    p = Program()
    p.mov_imm(0o100 if enable else 0, LKS)
    p.loop_forever()
    p.handler(0o100, 0o1400, lambda h: h.inc_abs(R[0]))
    return p


def idle_clock_counter():
    """Count clock interrupts at 2000, WAITing between them (as the FORTH's KEY does)."""
    p = Program()
    p.mov_imm(0o100, LKS)
    p.op("WAIT", 0o000001)
    p.op(f"BR {p.here - 2:o}", 0o000776)
    p.handler(0o100, 0o1400, lambda h: h.inc_abs(R[0]))
    return p


def drv_bits():
    p = Program()
    p.mov_imm(0o177777, DRV_CSR).mov_abs(DRV_CSR, R[0])   # 143: select, IE A/B
    p.movb_imm(0o377, DRV_CSR + 1).mov_abs(DRV_CSR, R[1]) # high byte: REQ B read-only
    p.movb_imm(0o2, DRV_CSR).mov_abs(DRV_CSR, R[2])       # low byte: select 2, IEs cleared
    p.clr_abs(DRV_CSR).mov_abs(DRV_CSR, R[3])
    p.mov_imm(0o123456, DRV_OUT).mov_abs(DRV_OUT, R[4])   # latch
    p.movb_imm(0o377, DRV_OUT + 1).mov_abs(DRV_OUT, R[5]) # high byte only
    p.movb_imm(0o0, DRV_OUT).mov_abs(DRV_OUT, R[6])       # low byte only
    p.clr_abs(DRV_OUT)
    p.mov_imm(0o1234, DRV_IN).mov_abs(DRV_IN, R[7])       # INBUF ignores writes
    p.mov_imm(0o103, DRV_CSR).mov_imm(0o17, DRV_OUT)
    p.reset().mov_abs(DRV_CSR, R[8]).mov_abs(DRV_OUT, R[9])  # INIT clears both
    return p.halt()


def drv_interrupts(csr):
    """Set the DRV11 CSR to `csr`, spin; handlers count at 2000 (A, 300) and 2002 (B, 304)."""
    p = Program()
    p.mov_imm(csr, DRV_CSR)
    p.loop_forever()
    p.handler(0o300, 0o1400, lambda h: h.inc_abs(R[0]))
    p.handler(0o304, 0o1420, lambda h: h.inc_abs(R[1]))
    return p


def aav_bits():
    p = Program()
    for i, a in enumerate(DAC):
        p.mov_abs(a, R[i])                                # 4000 at power-up
    p.mov_imm(0o177777, DAC[0]).mov_abs(DAC[0], R[4])     # 7777: bits 15:12 dropped
    p.mov_imm(0o4000, DAC[0])
    p.movb_imm(0o125, DAC[0]).mov_abs(DAC[0], R[5])       # low byte: 4125
    p.movb_imm(0o377, DAC[0] + 1).mov_abs(DAC[0], R[6])   # high byte: 7525
    p.mov_imm(0o1234, DAC[3]).mov_abs(DAC[3], R[7]).mov_abs(DAC[1], R[8])
    p.reset()
    for i, a in enumerate(DAC):
        p.mov_abs(a, R[9 + i])                            # INIT: 4000 again
    return p.halt()


def dac_step(codes, run_lines=0):
    """Write `codes` (x, y, z, t) to the DACs, optionally the run lines, then spin."""
    p = Program()
    if run_lines:
        p.mov_imm(run_lines, DRV_OUT)
    for code, a in zip(codes, DAC):
        p.mov_imm(code, a)
    return p.loop_forever()


def counter_wrap():
    """T runs flat out for 2.2 s with its counter running, stops, reads the counter
    and halts; continued, it drops t's run line and reads again, moves, raises the
    run line and reads after moving down."""
    p = Program()
    p.mov_imm(3, DRV_CSR)                                 # select t
    p.mov_imm(0o17, DRV_OUT)                              # all counters run
    p.mov_imm(0o7777, DAC[3])
    p.delay(660000)                                       # 2.2 s
    p.mov_imm(0o4000, DAC[3])
    p.delay(180000)                                       # 0.6 s: the axis stops
    p.mov_abs(DRV_IN, R[0])
    p.halt()                                              # the test looks at SHOW PLANT here
    p.mov_imm(0o7, DRV_OUT).mov_abs(DRV_IN, R[1])         # t held: 0
    p.mov_imm(0o3000, DAC[3])                             # move down while held
    p.delay(60000)
    p.mov_abs(DRV_IN, R[2])                               # still 0
    p.mov_imm(0o17, DRV_OUT)                              # counts again from here
    p.delay(60000)
    p.mov_abs(DRV_IN, R[3])                               # negative: two's complement
    p.mov_imm(0o4000, DAC[3])
    return p.halt()


RLCS, RLBA, RLDA, RLMP = 0o174400, 0o174402, 0o174404, 0o174406
TKS, TKB = 0o177560, 0o177562


def wait_ready(p, csr):
    """TSTB csr / BPL back: wait for bit 7 (ready)."""
    top = p.here
    p.op(f"TSTB @#{csr:o}", 0o105737, csr)
    return p.op(f"BPL {top:o}", 0o100375)


def rl_write_read():
    """SIMH's own RL11: write 256 words from 3000 to sector 0, read them back to 4000."""
    p = Program()
    for buffer, function in ((0o3000, 0o12), (0o4000, 0o14)):   # write data, read data
        p.mov_imm(buffer, RLBA).clr_abs(RLDA).mov_imm(0o177400, RLMP).mov_imm(function, RLCS)
        wait_ready(p, RLCS)
    p.mov_abs(RLCS, R[0])
    return p.halt()


def console_reader(count):
    """Read `count` characters from the console keyboard into 2000.., slowly."""
    p = Program()
    p.op("MOV #2000,R2", 0o012702, 0o2000)
    p.op(f"MOV #{count:o},R3", 0o012703, count)
    top = p.here
    wait_ready(p, TKS)
    p.op(f"MOVB @#{TKB:o},(R2)+", 0o113722, TKB)
    p.mov_imm_reg(0o4000, 0).sob_self(0)          # slower than characters arrive
    p.op(f"SOB R3,{top:o}", 0o077300 | ((p.here + 2 - top) // 2))
    return p.halt()


def gripper_steps(count, close, spacing):
    """`count` STEP pulses on DRV11 OUTBUF bit 4 (DIR bit 5 = close), `spacing`
    SOB iterations apart, counter run lines 17 kept; then the CSR to 2000."""
    dir_bit = 0o40 if close else 0
    p = Program()
    p.op(f"MOV #{count:o},R2", 0o012702, count)
    top = p.here
    p.mov_imm(0o17 | dir_bit, DRV_OUT).mov_imm(0o37 | dir_bit, DRV_OUT)
    p.mov_imm_reg(spacing, 0).sob_self(0)
    p.op(f"SOB R2,{top:o}", 0o077200 | ((p.here + 2 - top) // 2))
    p.mov_abs(DRV_CSR, R[0])
    return p.halt()


def all_programs():
    return {
        "lks_bits": lks_bits(), "clock_counter": clock_counter(),
        "idle_clock_counter": idle_clock_counter(),
        "drv_bits": drv_bits(), "drv_interrupts": drv_interrupts(0o140),
        "aav_bits": aav_bits(), "dac_step": dac_step([0o4144, 0o4144, 0o4144, 0o4144], 0o17),
        "counter_wrap": counter_wrap(), "rl_write_read": rl_write_read(),
        "console_reader": console_reader(10), "gripper_steps": gripper_steps(5, True, 100),
    }
