"""Hand-assembled programs for the timing tests, with their cost worked out by
hand from docs/kdf11-timing.md (memory management off)."""
from harness.analysis.pdp11prog import Program
from servo_program import LKS


def counting_handler():
    """Clock interrupts on, spin; the handler at 1400 saves R0, counts, restores."""
    p = Program()
    p.mov_imm(0o100, LKS).loop_forever()

    def body(h):
        h.op("MOV R0,-(SP)", 0o010046)           # 1.800 + 0 + 1.950 (dest g1 mode 4)
        h.inc_abs(0o2000)                        # 1.800 + 3.825 (dest g3 mode 3)
        h.op("MOV (SP)+,R0", 0o012600)           # 1.800 + 1.200 (src g1 mode 2)
    return p.handler(0o100, 0o1400, body)        # + RTI 5.550


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
