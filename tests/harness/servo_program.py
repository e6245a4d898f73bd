"""A small hand-assembled 60 Hz position servo for axis x, to make real traces.

It follows the paper's prose (not the printed code): within RANGE of the target
the axis is held at the zero-velocity code ZERO; otherwise the commanded velocity
VEL grows by INC each tick up to MAXVEL, and becomes the distance left once that
is smaller (DAC codes = counts). The main program idles, makes a long move and a
short one, then raises ZERO by one code three times (a stand-in for the 1983
servo's 0-Vel adaptation, so the held code changes over time). The handler uses
R2 and R3 only (the delay loops use R0 and R1), so it saves nothing.

Branch words were worked out by hand; tests/harness/test_servo_program.py checks
every word against SIMH's disassembler.
"""
from harness.analysis.pdp11prog import Program

TARGET, VEL, INC, MAXVEL, ZERO, RANGE = (0o2000 + 2 * i for i in range(6))
LKS, DRV_OUT, DRV_IN, DAC_X = 0o177546, 0o167772, 0o167774, 0o170440
HANDLER = 0o1400
HANDLER_RTI = (0o1436, 0o1522)      # the handler's two RTIs (hold, move)

RATE = 300_000                       # instructions per simulated second (default)
LONG_TARGET, SHORT_TARGET = 3000, 2850
SETTINGS = dict(inc=20, maxvel=300, zero=2048, range_=5)


def _handler(h):
    h.op("MOV @#2000,R2", 0o013702, TARGET)              # 1400
    h.op("SUB @#167774,R2", 0o163702, DRV_IN)            # 1404 R2 = target - pos
    h.op("MOV R2,R3", 0o010203)                          # 1410
    h.op("BPL 1416", 0o100001)                           # 1412
    h.op("NEG R3", 0o005403)                             # 1414 R3 = |distance|
    h.op("CMP R3,@#2012", 0o020337, RANGE)               # 1416
    h.op("BGE 1440", 0o002006)                           # 1422 out of range: move
    h.op("MOV @#2010,@#170440", 0o013737, ZERO, DAC_X)   # 1424 hold at ZERO
    h.op("CLR @#2002", 0o005037, VEL)                    # 1432
    h.op("RTI", 0o000002)                                # 1436
    h.op("CMP R3,@#2002", 0o020337, VEL)                 # 1440 distance < VEL?
    h.op("BGE 1454", 0o002003)                           # 1444
    h.op("MOV R3,@#2002", 0o010337, VEL)                 # 1446 VEL = distance
    h.op("BR 1500", 0o000412)                            # 1452
    h.op("ADD @#2004,@#2002", 0o063737, INC, VEL)        # 1454 VEL += INC
    h.op("CMP @#2002,@#2006", 0o023737, VEL, MAXVEL)     # 1462
    h.op("BLE 1500", 0o003403)                           # 1470
    h.op("MOV @#2006,@#2002", 0o013737, MAXVEL, VEL)     # 1472 VEL = MAXVEL
    h.op("MOV @#2002,R3", 0o013703, VEL)                 # 1500
    h.op("TST R2", 0o005702)                             # 1504 direction
    h.op("BPL 1512", 0o100001)                           # 1506
    h.op("NEG R3", 0o005403)                             # 1510
    h.op("ADD @#2010,R3", 0o063703, ZERO)                # 1512
    h.op("MOV R3,@#170440", 0o010337, DAC_X)             # 1516 output; RTI follows


def seconds(s):
    return int(s * RATE)


def servo_program(long_target=LONG_TARGET, short_target=SHORT_TARGET, inc=20,
                  maxvel=300, zero=2048, range_=5, adapt_steps=3):
    p = Program()
    p.mov_imm(0o17, DRV_OUT)                             # counters run; x selected
    p.clr_abs(TARGET).clr_abs(VEL)
    for addr, value in ((INC, inc), (MAXVEL, maxvel), (ZERO, zero), (RANGE, range_)):
        p.mov_imm(value, addr)
    p.mov_imm(0o100, LKS)                                # 60 Hz interrupts on
    p.delay(seconds(0.3))                                # idle first
    p.mov_imm(long_target, TARGET).delay(seconds(1.5))   # the long move
    p.mov_imm(short_target, TARGET).delay(seconds(0.8))  # the short move
    for _ in range(adapt_steps):
        p.inc_abs(ZERO).delay(seconds(0.3))              # the held code rises
    p.halt()
    p.handler(0o100, HANDLER, _handler)
    return p


def trace_script(program, trace_path, extra=""):
    """SIMH lines: load the program, trace the plant to `trace_path`, run to HALT."""
    return (program.script(start=False) + extra + f"attach plant {trace_path}\n"
            f"go {program.origin:o}\ndetach plant\n")
