"""Hand-assembled programs for the timing tests, with their cost worked out by
hand from docs/kdf11-timing.md (memory management off)."""
from harness.analysis.pdp11prog import Program
from servo_program import LKS


def _count(h):
    h.op("MOV R0,-(SP)", 0o010046)               # 1.800 + 0 + 1.950 (dest g1 mode 4)
    h.inc_abs(0o2000)                            # 1.800 + 3.825 (dest g3 mode 3)
    h.op("MOV (SP)+,R0", 0o012600)               # 1.800 + 1.200 (src g1 mode 2)


def counting_handler():
    """Clock interrupts on, spin; the handler at 1400 saves R0, counts, restores."""
    p = Program()
    p.mov_imm(0o100, LKS).loop_forever()
    return p.handler(0o100, 0o1400, _count)      # + RTI 5.550


HANDLER_US = 3.75 + 5.625 + 3.0 + 5.55 + 9.375  # + the interrupt entry estimate: 27.3


def call_program():
    """Straight-line code from 1000 through ADD at 1010, then a spin."""
    p = Program()
    p.mov_imm_reg(5, 0)                          # 1000 MOV #5,R0: 1.800 + 1.200
    p.sob_self(0)                                # 1004 SOB: 4 taken 2.700, 1 not 2.400
    p.op("CLR R1", 0o005001)                     # 1006 1.800
    p.op("ADD #7,R1", 0o062701, 7)               # 1010 1.800 + 1.200
    return p.loop_forever()                      # 1014


CALL_US = 3.0 + 4 * 2.7 + 2.4 + 1.8 + 3.0       # 21.0


def mixed_program(passes=2000):
    """Clock interrupts (counting_handler's handler) over `passes` rounds of a
    SOB delay and a TRAP (its handler at 1500 clears R1), then HALT: spans
    with nested interrupts, SOB taken and not, a trap's RTI, a stop."""
    p = Program()
    p.mov_imm(0o100, LKS).mov_imm_reg(passes, 2)                 # 1000, 1006
    top = p.here                                                 # 1012
    p.mov_imm_reg(3, 0).sob_self(0)                              # 1012, 1016
    p.op("TRAP 0", 0o104400)                                     # 1020
    p.op(f"SOB R2,{top:o}", 0o077200 | (p.here + 2 - top) // 2)  # 1022
    p.halt()                                                     # 1024
    p.handler(0o100, 0o1400, _count)
    return p.handler(0o34, 0o1500, lambda h: h.op("CLR R1", 0o005001))
