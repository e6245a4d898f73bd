"""The appendix's CODE words (blocks 1000-1008) through the host assembler,
against a MACRO-11 translation made by hand (tests/asm/appendix/servo.mac)
assembled by pdpy11: the destination-first reading of the 1983 code, checked
on the real thing, with its nesting and branch distances."""
from pathlib import Path

from tests.asm.asmcheck import corpus, host_asm, simh_disasm
from tests.lazy import lazy

pdpy11_ref = lazy("tests.asm.asmcheck.pdpy11_ref")   # pdpy11, at the test

APPENDIX = Path(__file__).resolve().parent / "appendix"


def host_words(sixteen=False):
    """Words the host assembler gives for servo.fs, from 001000."""
    source = "\n".join(corpus.forth_for_host(line) if not line.startswith("\\") else ""
                       for line in (APPENDIX / "servo.fs").read_text().splitlines())

    def loader(tmp):
        base = (host_asm.sixteen_loader if sixteen else host_asm.host_loader)(tmp)
        return base + [str(APPENDIX / "prelude.fs")]
    script = (f"{corpus.ORIGIN} ahere-var !\n{source}\n"
              f"{corpus.ORIGIN} origin ! .( words: ) words. cr bye\n")
    out = host_asm.gforth(loader, script)
    line = [l for l in out.splitlines() if l.startswith("words:")]
    assert line, out[-2000:]
    return [int(w, 8) for w in line[0].split()[1:]]


def test_servo_code_matches_the_macro11_translation():
    forth = host_words()
    macro = pdpy11_ref.assemble_source((APPENDIX / "servo.mac").read_text())
    assert len(macro) > 100
    listing = simh_disasm.disassemble([forth])[0]
    assert forth == macro, "\n".join(
        f"{corpus.ORIGIN + 2 * i:06o} {a:06o} {b:06o}"
        for i, (a, b) in enumerate(zip(forth, macro)) if a != b) + "\n" + "\n".join(listing)


def test_servo_code_is_the_same_with_16_bit_cells():
    assert host_words(sixteen=True) == host_words()
