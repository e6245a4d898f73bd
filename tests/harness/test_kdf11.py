"""The KDF11-A pricer against the worked examples of docs/kdf11-timing.md and
the table's structure (basic + source + destination)."""
import pytest

from harness.analysis.kdf11 import price


@pytest.mark.parametrize("word, name, us", [
    (0o010046, "MOV", 3.75),      # MOV R0,-(SP): 1.800 + 0 + 1.950 (doc's example)
    (0o016161, "MOV", 7.50),      # MOV 2000(R1),170440(R1): 1.800 + 2.700 + 3.000
    (0o000134, "JMP", 3.00),      # JMP @(R4)+ = NEXT
    (0o005000, "CLR", 1.80),      # CLR R0
    (0o006301, "ASL", 1.80),      # ASL R1
    (0o020027, "CMP", 1.80 + 0 + 1.50),        # CMP R0,#4 (dest mode 2, group 2)
    (0o026702, "CMP", 1.80 + 2.70 + 0),        # CMP 2(PC)... src mode 6
    (0o066161, "ADD", 1.80 + 2.70 + 4.125),    # ADD X(R1),Y(R1)
    (0o105737, "TSTB", 1.80 + 2.40),           # TSTB @#a
    (0o106427, "MTPS", 3.375 + 1.50),          # MTPS #340: corrected group 2 mode 2
    (0o106737, "MFPS", 1.80 + 2.70),           # MFPS @#a
    (0o000002, "RTI", 5.55),
    (0o001402, "BEQ", 1.80),
    (0o100402, "BMI", 1.80),
    (0o070001, "MUL", 33.075 + 1.275),         # MUL R1,R0
    (0o004767, "JSR", 5.10),                   # JSR PC,X(PC): B-7 mode 6
    (0o000207, "RTS", 3.30),
    (0o000241, "CCOP", 2.70),                  # CLC
    (0o104400, "TRAP", 8.85),
])
def test_examples(word, name, us):
    p = price(word)
    assert p.mnemonic == name
    assert p.microseconds == pytest.approx(us)


def test_sob_taken_and_not():
    assert price(0o077102, sob_taken=True).microseconds == pytest.approx(2.70)
    assert price(0o077102, sob_taken=False).microseconds == pytest.approx(2.40)


def test_unpriced_and_invalid():
    assert price(0o000005).microseconds is None          # RESET: not in the tables
    with pytest.raises(ValueError, match="not a PDP-11/23 instruction"):
        price(0o170000)                                    # FPP: not priced here
