"""Price executed PDP-11 instructions on a KDF11-A (PDP-11/23), memory management off.

Time = basic + source + destination (DEC KDF11-B User's Guide, Appendix B, tables
B-4..B-7, as transcribed in docs/kdf11-timing.md; the "MMU off" column). JMP and
JSR take their B-7 whole time; branches, SOB, RTS, RTI, RTT, MARK, traps, WAIT and the
condition-code operators cost their basic time alone.

Where the transcription marks an entry as a likely copying error and gives the likely
value, that value is used (source group 2 modes 1 and 2: 1.500; destination group 1
mode 7: 4.200; MTPI/MTPD basic: 4.275). Entries marked doubtful without an alternative
(destination group 1 mode 4: 1.950; EMT/TRAP: 8.850) are used as printed.

Pure logic: no I/O. `price(word)` takes one instruction word (the opcode; operand
words do not change the price) and returns microseconds.
"""
from dataclasses import dataclass

# B-4 source, by mode: group 1 (double operand), group 2 (EIS, MTPS, MFPI/D).
SOURCE_G1 = (0.0, 1.200, 1.200, 2.400, 1.500, 2.700, 2.700, 3.900)
SOURCE_G2 = (1.275, 1.500, 1.500, 2.400, 1.500, 2.700, 2.700, 3.900)

# B-5 destination, by mode: group 1 write-only, group 2 read-only,
# group 3 read-modify-write.
DEST_G1 = (0.0, 1.800, 1.800, 2.700, 1.950, 3.000, 3.000, 4.200)
DEST_G2 = (0.0, 1.500, 1.500, 2.400, 1.500, 2.700, 2.700, 3.900)
DEST_G3 = (0.0, 2.625, 2.625, 3.825, 2.625, 4.125, 4.125, 5.325)

# B-7 whole times by mode (mode 0 is illegal for both: it traps).
JMP_TIME = (None, 2.100, 2.400, 3.000, 2.400, 3.300, 3.300, 4.500)
JSR_TIME = (None, 3.900, 4.200, 4.800, 4.200, 5.100, 5.100, 6.300)

BASIC = 1.800           # double and single operand group, branches
SOB_TAKEN, SOB_NOT_TAKEN = 2.700, 2.400
CC_OP = 2.700
INTERRUPT_ENTRY = 9.375  # not in the tables: estimated as IOT's trap sequence

DEST_GROUPS = {1: DEST_G1, 2: DEST_G2, 3: DEST_G3}


@dataclass(frozen=True)
class Priced:
    mnemonic: str
    microseconds: float | None   # None: the tables give no figure (HALT, RESET, MFPT)


def _mode(field6: int) -> int:
    return (field6 >> 3) & 7


# Double-operand opcodes (bits 14:12) -> (mnemonic, destination group).
_DOUBLE = {1: ("MOV", 1), 2: ("CMP", 2), 3: ("BIT", 2), 4: ("BIC", 3), 5: ("BIS", 3)}
# Single-operand opcodes (bits 15:6 with the byte bit cleared) -> (mnemonic, group).
_SINGLE = {
    0o0050: ("CLR", 1), 0o0051: ("COM", 1), 0o0052: ("INC", 3), 0o0053: ("DEC", 3),
    0o0054: ("NEG", 3), 0o0055: ("ADC", 3), 0o0056: ("SBC", 3), 0o0057: ("TST", 2),
    0o0060: ("ROR", 3), 0o0061: ("ROL", 3), 0o0062: ("ASR", 3), 0o0063: ("ASL", 3),
    0o0067: ("SXT", 1),
}
_EIS = {0o070: ("MUL", 33.075), 0o071: ("DIV", 49.425), 0o072: ("ASH", 24.600),
        0o073: ("ASHC", 45.825)}
_ZERO_OPERAND = {0o000000: ("HALT", None), 0o000001: ("WAIT", 3.150),
                 0o000002: ("RTI", 5.550), 0o000003: ("BPT", 9.375),
                 0o000004: ("IOT", 9.375), 0o000005: ("RESET", None),
                 0o000006: ("RTT", 6.825), 0o000007: ("MFPT", None)}
# Branch opcodes (word & 177400).
_BRANCHES = {0o000400: "BR", 0o001000: "BNE", 0o001400: "BEQ", 0o002000: "BGE",
             0o002400: "BLT", 0o003000: "BGT", 0o003400: "BLE", 0o100000: "BPL",
             0o100400: "BMI", 0o101000: "BHI", 0o101400: "BLOS", 0o102000: "BVC",
             0o102400: "BVS", 0o103000: "BCC", 0o103400: "BCS"}
# Special single-operand-format opcodes (word >> 6) -> (mnemonic, basic, operand table).
_SPECIAL = {0o0003: ("SWAB", BASIC, DEST_G3), 0o1064: ("MTPS", 3.375, SOURCE_G2),
            0o1067: ("MFPS", BASIC, DEST_G1), 0o0065: ("MFPI", 3.600, SOURCE_G2),
            0o1065: ("MFPD", 3.600, SOURCE_G2), 0o0066: ("MTPI", 4.275, DEST_G1),
            0o1066: ("MTPD", 4.275, DEST_G1)}


def price(word: int, sob_taken: bool = True) -> Priced:
    """The KDF11-A time of the instruction whose first word is `word`."""
    word &= 0o177777
    byte = word >> 15
    op4 = (word >> 12) & 7
    src, dst = (word >> 6) & 0o77, word & 0o77
    suffix = "B" if byte else ""

    if op4 in _DOUBLE:                                  # MOV CMP BIT BIC BIS (+B)
        name, group = _DOUBLE[op4]
        return Priced(name + suffix,
                      BASIC + SOURCE_G1[_mode(src)] + DEST_GROUPS[group][_mode(dst)])
    if op4 == 6:                                        # ADD / SUB
        name = "SUB" if byte else "ADD"
        return Priced(name, BASIC + SOURCE_G1[_mode(src)] + DEST_G3[_mode(dst)])
    if word >> 9 in _EIS and not byte:                  # MUL DIV ASH ASHC
        name, basic = _EIS[word >> 9]
        return Priced(name, basic + SOURCE_G2[_mode(dst)])
    if word >> 9 == 0o074:                              # XOR: MOV basic + group 3
        return Priced("XOR", BASIC + DEST_G3[_mode(dst)])
    if word >> 9 == 0o077:
        return Priced("SOB", SOB_TAKEN if sob_taken else SOB_NOT_TAKEN)

    top10 = word >> 6
    if top10 in _SPECIAL:
        name, basic, table = _SPECIAL[top10]
        return Priced(name, basic + table[_mode(dst)])
    if (top10 & 0o777) in _SINGLE:                    # CLR..ASL, SXT (+B)
        name, group = _SINGLE[top10 & 0o777]
        return Priced(name + suffix, BASIC + DEST_GROUPS[group][_mode(dst)])
    if top10 == 0o0001:
        return Priced("JMP", JMP_TIME[_mode(dst)])
    if word >> 9 == 0o004:
        return Priced("JSR", JSR_TIME[_mode(dst)])
    if word & 0o177770 == 0o000200:
        return Priced("RTS", 3.300)
    if word & 0o177700 == 0o006400:
        return Priced("MARK", 4.875)
    if word & 0o177740 == 0o000240:
        return Priced("NOP" if word in (0o240, 0o260) else "CCOP", CC_OP)
    if word & 0o177400 in (0o104000, 0o104400):
        return Priced("EMT" if word < 0o104400 else "TRAP", 8.850)
    if word in _ZERO_OPERAND:
        name, t = _ZERO_OPERAND[word]
        return Priced(name, t)
    if word & 0o177400 in _BRANCHES:
        return Priced(_BRANCHES[word & 0o177400], BASIC)
    raise ValueError(f"{word:06o} is not a PDP-11/23 instruction the tables price")
