"""The resident ASSEMBLER (forth/asm.fs metacompiled into the kernel through
forth/asm-target.fs) on the emulated 11/23, on the same corpus: the same words
as the host assembler (itself checked against pdpy11 and SIMH), and the same
refusals of bad input, with nothing emitted by the failing instruction."""
from pathlib import Path

import pytest

from tests.asm.asmcheck import corpus, host_asm, resident

HERE = Path(__file__).resolve().parent


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    good = [u for name in ("corpus.txt", "handwritten.txt") for u in corpus.read(HERE / name)]
    bad = corpus.read(HERE / "errors.txt")
    words, errors = resident.assemble([u.forth for u in good], [u.forth for u in bad],
                                      tmp_path_factory.mktemp("resident"))
    return good, words, bad, errors


def test_resident_assembler_gives_the_host_words(run):
    good, words, _, _ = run
    host = host_asm.assemble([u.forth for u in good])
    diff = [f"{u.source}: {u.forth!r}: machine {w}, host {h.words}"
            for u, w, h in zip(good, words, host) if w != h.words]
    assert len(good) > 1000
    assert not diff, f"{len(diff)} units differ:\n" + "\n".join(diff[:30])


def test_resident_assembler_refuses_bad_input(run):
    _, _, bad, errors = run
    diff = [f"{u.source}: {u.forth!r}: machine said {e!r} after {n} word(s), "
            f"want {u.error!r} after {u.emitted}"
            for u, (e, n) in zip(bad, errors)
            if not e.startswith(u.error) or n != u.emitted]
    assert not diff, "\n".join(diff)
