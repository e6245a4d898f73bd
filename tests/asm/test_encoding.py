"""The host assembler (forth/asm.fs under gforth) against two independent references.

Corpus: tests/asm/corpus.txt (generated, every instruction x every mode it takes)
and tests/asm/handwritten.txt (docs/design.md's examples and the appendix's lines,
by hand). Each unit pairs FORTH text with MACRO-11 text and must give the same
words from (a) pdpy11 on the MACRO-11 text and (c) the host assembler on the
FORTH text, and (b) SIMH's disassembler must read the host's words back as the
MACRO-11 text."""
import re
from pathlib import Path

import pytest

from tests.asm.asmcheck import corpus, gen_corpus, host_asm, simh_disasm
from tests.lazy import lazy

pdpy11_ref = lazy("tests.asm.asmcheck.pdpy11_ref")   # pdpy11, at the test

HERE = Path(__file__).resolve().parent
ASM = HERE.parent.parent / "forth" / "asm.fs"
CORPUS_FILES = [HERE / "corpus.txt", HERE / "handwritten.txt"]


def octal(words):
    return " ".join(f"{w:06o}" for w in words)


def report(bad, what):
    lines = [f"{len(bad)} unit(s) where {what}:"] + bad[:30]
    return "\n".join(lines)


@pytest.fixture(scope="module")
def units():
    return [u for path in CORPUS_FILES for u in corpus.read(path)]


@pytest.fixture(scope="module")
def host(units):
    return host_asm.assemble([u.forth for u in units])


def test_generated_corpus_is_current(capsys):
    gen_corpus.main()
    assert capsys.readouterr().out == (HERE / "corpus.txt").read_text(), \
        "regenerate: python -m tests.asm.asmcheck.gen_corpus > tests/asm/corpus.txt"


def test_corpus_covers_every_instruction(units):
    """Every instruction and structure word asm.fs defines appears in the corpus."""
    source = ASM.read_text()
    defined = {w for w in re.findall(r"(?:^|\s): (\S+,)", source) if not w.startswith("ASM-")}
    used = {t for u in units for t in u.forth.split()}
    assert len(defined) > 90
    assert defined - used == set()


# The words forth/asm.fs may use (forth/ASSEMBLER.md: the subset the
# metacompiler compiles for the target), plus the includer's four.
PORTABLE = set("""
    : ; CREATE DOES> , @ ! +! IF ELSE THEN BEGIN UNTIL WHILE REPEAT DO LOOP
    CONSTANT VARIABLE ABORT" DEPTH DUP DROP SWAP OVER ROT >R R> R@
    AND OR XOR + - * 2/ < > = <> 0= 0> 1- ( A, AHERE A@ A!""".split())


def test_asm_uses_only_the_portable_subset():
    text = re.sub(r'ABORT" [^"]*"', 'ABORT"', ASM.read_text())
    text = re.sub(r"(?<!\S)\( [^)]*\)", " ", text)
    tokens = text.upper().split()
    defining = {"VARIABLE", "CONSTANT", ":"}
    for i, t in enumerate(tokens[:-1]):       # colon words that CREATE define too
        if t == ":":
            body = tokens[i + 2:tokens.index(";", i)]
            if "CREATE" in body:
                defining.add(tokens[i + 1])
    defined = {tokens[i + 1] for i, t in enumerate(tokens[:-1]) if t in defining}
    other = {t for t in tokens if t not in PORTABLE | defined and not re.fullmatch(r"-?\d+", t)}
    assert other == set()


def test_host_assembles_every_unit(units, host):
    bad = [f"{u.source}: {u.forth!r}: {r.error}" for u, r in zip(units, host) if r.error]
    assert not bad, report(bad, "the host assembler refused good input")


def test_pdpy11_agrees_with_host(units, host):
    bad = []
    for u, r, ref in zip(units, host, pdpy11_ref.assemble_each([u.macro for u in units])):
        if isinstance(ref, pdpy11_ref.ReferenceError):
            bad.append(f"{u.source}: {ref}")
        elif list(r.words) != ref:
            bad.append(f"{u.source}: {u.forth!r} -> {octal(r.words)}; "
                       f"pdpy11 {' ; '.join(u.macro)!r} -> {octal(ref)}")
    assert not bad, report(bad, "pdpy11 and the host assembler differ")


def test_simh_disassembles_host_words_as_macro_text(units, host):
    listing = simh_disasm.disassemble([r.words for r in host])
    bad = []
    for u, r, got in zip(units, host, listing):
        expected = [simh_disasm.normalise(s) for s in u.macro]
        if got != expected:
            bad.append(f"{u.source}: {u.forth!r} -> {octal(r.words)}: SIMH {got}, "
                       f"corpus {expected}")
    assert not bad, report(bad, "SIMH reads the host's words differently")


def test_units_give_the_same_words_anywhere(units, host):
    """Branch targets are written relative to AHERE, so the resident assembler can
    assemble the corpus at HERE and be compared with the same words."""
    elsewhere = host_asm.assemble([u.forth for u in units], origin=0o40000)
    bad = [f"{u.source}: {u.forth!r}: {octal(a.words)} at 001000, {octal(b.words)} "
           f"at 040000" for u, a, b in zip(units, host, elsewhere) if a != b]
    assert not bad, report(bad, "the words depend on where the unit is assembled")


def test_sixteen_bit_cells_give_the_same_words(units, host):
    """As the resident ASSEMBLER will run it: 16-bit cells, high addresses."""
    target = host_asm.assemble([u.forth for u in units], origin=0o120000, sixteen=True)
    bad = [f"{u.source}: {u.forth!r}: {octal(a.words)} with host cells, "
           f"{octal(b.words) or b.error} with 16-bit cells"
           for u, a, b in zip(units, host, target) if a != b]
    assert not bad, report(bad, "16-bit cells change the result")


@pytest.mark.parametrize("sixteen", [False, True], ids=["host-cells", "16-bit-cells"])
def test_bad_input_aborts_with_message_and_emits_nothing(sixteen):
    units = corpus.read(HERE / "errors.txt")
    results = host_asm.assemble([u.forth for u in units], origin=0o120000 if sixteen
                                else corpus.ORIGIN, sixteen=sixteen)
    bad = [f"{u.source}: {u.forth!r}: got {r.error or octal(r.words)!r} after "
           f"{r.emitted} word(s), want {u.error!r} after {u.emitted}"
           for u, r in zip(units, results)
           if not r.error.startswith(u.error) or r.emitted != u.emitted]
    assert len(units) > 40
    assert not bad, report(bad, "bad input was not refused as expected")


def test_after_an_error_the_next_instruction_is_clean():
    """An error resets the operand slots: the following unit is not disturbed."""
    results = host_asm.assemble(["5 # R0 MOV,", "R0 CLR,", "R0 R1 R2 MOV,", "R1 R2 ADD,"])
    assert [r.words for r in results] == [(), (0o005000,), (), (0o060201,)]
