"""Writes tests/asm/corpus.txt: every instruction with every addressing mode it takes.

Each line pairs the FORTH (destination-first) text with the MACRO-11 text of the
same instruction, so the two cannot drift apart; the three independent checks
(pdpy11, SIMH, the host assembler) then judge both sides. The operand order of
the pairs is written out here once; tests/asm/handwritten.txt pins it down by
hand with the examples of docs/design.md and the appendix blocks.

    python -m tests.asm.asmcheck.gen_corpus > tests/asm/corpus.txt
"""
from dataclasses import dataclass

from .corpus import ORIGIN

MACRO_REG = ["R0", "R1", "R2", "R3", "R4", "R5", "SP", "PC"]


@dataclass(frozen=True)
class Operand:
    forth: str
    kind: str          # "reg", "mem" or "imm"
    macro_text: str    # MACRO-11 text; {target} is filled in for PC-relative
    index: int = None  # the index of a PC-relative operand

    def macro(self, extra_addr):
        """MACRO-11 text, the extra word (if any) being at extra_addr."""
        if self.index is None:
            return self.macro_text
        return self.macro_text.format(target=f"{(extra_addr + 2 + self.index) & 0xFFFF:o}")


def octal(n):
    return f"{n:o}O"


def here(delta):
    """A branch target as FORTH text relative to AHERE, so that a unit gives the
    same words wherever it is assembled (on the target, at HERE)."""
    if delta == 0:
        return "AHERE"
    return f"AHERE {octal(abs(delta))} {'+' if delta > 0 else '-'}"


def operands(r, base):
    """The twelve ways of addressing, on register r (0-5), numbers from base."""
    R = f"R{r}"
    return [
        Operand(R, "reg", R),
        Operand(f"{R} )", "mem", f"({R})"),
        Operand(f"{R} )+", "mem", f"({R})+"),
        Operand(f"{R} @)+", "mem", f"@({R})+"),
        Operand(f"{R} -)", "mem", f"-({R})"),
        Operand(f"{R} @-)", "mem", f"@-({R})"),
        Operand(f"{octal(base)} {R} I)", "mem", f"{base:o}({R})"),
        Operand(f"{octal(base + 2)} {R} @I)", "mem", f"@{base + 2:o}({R})"),
        Operand(f"{octal(base + 0o1000)} #", "imm", f"#{base + 0o1000:o}"),
        Operand(f"{octal(base + 0o2000)} @#", "mem", f"@#{base + 0o2000:o}"),
        Operand(f"{octal(base + 4)} PC I)", "mem", "{target}", base + 4),
        Operand(f"{octal(base + 6)} PC @I)", "mem", "@{target}", base + 6),
    ]


def has_extra(op):
    """Indexed, immediate and absolute operands start with their number."""
    return op.forth.split()[0][0].isdigit()


def layout(*ops):
    """MACRO-11 texts of the operands in emission order (source first), each
    knowing where its extra word lands."""
    addr, texts = ORIGIN + 2, []
    for op in ops:
        texts.append(op.macro(addr))
        if has_extra(op):
            addr += 2
    return texts


def double(name, dst, src):
    s, d = layout(src, dst)
    return f"{dst.forth} {src.forth} {name},", f"{name} {s},{d}"


def single(name, dst):
    (d,) = layout(dst)
    return f"{dst.forth} {name},", f"{name} {d}"


SRC = operands(1, 0o12)
DST = operands(3, 0o22)
REG_ONLY = [Operand(f"R{r}", "reg", MACRO_REG[r]) for r in range(8)]
WRITABLE = [d for d in DST if d.kind != "imm"]
MEMORY = [d for d in DST if d.kind == "mem"]

DOUBLE_WRITE = ["MOV", "MOVB", "BIC", "BICB", "BIS", "BISB", "ADD", "SUB"]
DOUBLE_READ = ["CMP", "CMPB", "BIT", "BITB"]
SINGLE_WRITE = ["CLR", "CLRB", "COM", "COMB", "INC", "INCB", "DEC", "DECB", "NEG",
                "NEGB", "ADC", "ADCB", "SBC", "SBCB", "ROR", "RORB", "ROL", "ROLB",
                "ASR", "ASRB", "ASL", "ASLB", "SWAB", "SXT", "MFPS", "MTPI", "MTPD"]
SINGLE_READ = ["TST", "TSTB", "MTPS", "MFPI", "MFPD"]
NO_OPERAND = ["HALT", "WAIT", "RTI", "BPT", "IOT", "RESET", "RTT", "MFPT", "NOP",
              "CLC", "CLV", "CLZ", "CLN", "CCC", "SEC", "SEV", "SEZ", "SEN", "SCC"]
BRANCHES = ["BR", "BNE", "BEQ", "BGE", "BLT", "BGT", "BLE", "BPL", "BMI", "BHI",
            "BLOS", "BVC", "BVS", "BCC", "BCS", "BHIS", "BLO"]
# condition: (branch taken when it holds, branch taken when it fails)
CONDITIONS = {"EQ": ("BEQ", "BNE"), "NE": ("BNE", "BEQ"), "MI": ("BMI", "BPL"),
              "PL": ("BPL", "BMI"), "CS": ("BCS", "BCC"), "CC": ("BCC", "BCS"),
              "VS": ("BVS", "BVC"), "VC": ("BVC", "BVS"), "LT": ("BLT", "BGE"),
              "GE": ("BGE", "BLT"), "LE": ("BLE", "BGT"), "GT": ("BGT", "BLE"),
              "HI": ("BHI", "BLOS"), "LOS": ("BLOS", "BHI"), "HIS": ("BHIS", "BLO"),
              "LO": ("BLO", "BHIS")}


def units():
    """(FORTH, MACRO-11) pairs, section by section; None starts a new section."""
    yield "double operand: every source mode, every destination mode", None
    for name in DOUBLE_WRITE + DOUBLE_READ:
        for src in SRC:
            yield double(name, REG_ONLY[0], src)
        for dst in (WRITABLE if name in DOUBLE_WRITE else DST):
            yield double(name, dst, REG_ONLY[2])
    yield "MOV: every source mode with every destination mode, every register", None
    for src in SRC:
        for dst in WRITABLE:
            yield double("MOV", dst, src)
    for r in range(8):
        yield double("MOV", REG_ONLY[r], REG_ONLY[7 - r])
    yield "single operand", None
    for name in SINGLE_WRITE + SINGLE_READ:
        for dst in (WRITABLE if name in SINGLE_WRITE else DST):
            yield single(name, dst)
    yield "JMP JSR RTS", None
    for dst in MEMORY:
        yield single("JMP", dst)
        (d,) = layout(dst)
        yield f"{dst.forth} R5 JSR,", f"JSR R5,{d}"
    for r in range(8):
        yield f"R1 ) R{r} JSR,", f"JSR {MACRO_REG[r]},(R1)"
        yield f"R{r} RTS,", f"RTS {MACRO_REG[r]}"
    yield "EIS: reg src MUL, = MUL src,reg; dst reg XOR, = XOR reg,dst", None
    for name in ["MUL", "DIV", "ASH", "ASHC"]:
        for src in SRC:
            (s,) = layout(src)
            yield f"R2 {src.forth} {name},", f"{name} {s},R2"
        for r in range(0, 8, 2 if name == "DIV" else 1):
            yield f"R{r} R1 {name},", f"{name} R1,{MACRO_REG[r]}"
    for dst in WRITABLE:
        (d,) = layout(dst)
        yield f"{dst.forth} R2 XOR,", f"XOR R2,{d}"
    for r in range(8):
        yield f"R1 R{r} XOR,", f"XOR {MACRO_REG[r]},R1"
    yield "SOB: addr reg SOB, (0 to 63 words back)", None
    for r in range(8):
        yield f"{here(2)} R{r} SOB,", f"SOB {MACRO_REG[r]},1002"
    yield f"{here(0)} R3 SOB,", "SOB R3,1000"
    yield f"{here(-0o174)} R4 SOB,", "SOB R4,604"
    yield "no operand, numbers", None
    for name in NO_OPERAND:
        yield f"{name},", name
    for name, top in [("EMT", 0o377), ("TRAP", 0o377), ("MARK", 0o77)]:
        for n in (0, 1, top):
            yield f"{octal(n)} {name},", f"{name} {n:o}"
    yield "branches to an address: addr Bxx, (offsets 0, -1, 127, -128)", None
    for name in BRANCHES:
        for target in (0o1002, 0o1000, 0o1400, 0o402):
            yield f"{here(target - ORIGIN)} {name},", f"{name} {target:o}"
    yield "structured control with every condition", None
    for cond, (taken, fails) in CONDITIONS.items():
        yield f"{cond} IF, R0 INC, THEN,", f"{fails} 1004 ; INC R0"
        yield (f"{cond} IF, R0 INC, ELSE, R1 INC, THEN,",
               f"{fails} 1006 ; INC R0 ; BR 1010 ; INC R1")
        yield f"BEGIN, R0 DEC, {cond} UNTIL,", f"DEC R0 ; {fails} 1000"
        yield f"BEGIN, R0 DEC, {cond} END,", f"DEC R0 ; {fails} 1000"
        yield (f"BEGIN, R0 TST, {cond} WHILE, R0 DEC, REPEAT,",
               f"TST R0 ; {fails} 1010 ; DEC R0 ; BR 1000")
    yield "BEGIN, R0 INC, AGAIN,", "INC R0 ; BR 1000"
    yield "BEGIN, AGAIN,", "BR 1000"
    yield "EQ IF, THEN,", "BNE 1002"
    yield "NEXT,", "JMP @(R4)+"


def main():
    print("# Generated by tests/asm/asmcheck/gen_corpus.py: do not edit, regenerate.")
    print("# FORTH (destination first) | MACRO-11 at 001000 (octal; branch and")
    print("# PC-relative targets absolute; statements separated by ' ; ')")
    for forth, macro in units():
        if macro is None:
            print(f"\n# {forth}")
        else:
            print(f"{forth:<34} | {macro}")


if __name__ == "__main__":
    main()
