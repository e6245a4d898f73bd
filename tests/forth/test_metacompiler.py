"""The metacompiler: forward references resolved or reported, errors named by
file and line, the absolute-loader file and the map consistent with the kernel."""
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LDA = ROOT / "build" / "kernel.lda"
MAP = ROOT / "build" / "kernel.map"


def metacompile(tmp_path, source):
    """Run the metacompiler on the kernel's first files plus `source`."""
    src = tmp_path / "unit.fs"
    src.write_text(source)
    driver = tmp_path / "driver.fs"
    driver.write_text(
        f"require {ROOT}/forth/meta/load.fs\n"
        "$400 tdp !\n"
        's" forth/kernel/memory.fs" meta-include\n'
        's" forth/kernel/prims.fs" meta-include\n'
        f's" {src}" meta-include\n'
        'fwd-report [if] .( unresolved) cr 1 (bye) [then]\n'
        ".( metacompiled) cr bye\n")
    return subprocess.run(["gforth", str(driver)], cwd=ROOT, capture_output=True,
                          text=True, timeout=60)


def test_forward_reference_is_resolved(tmp_path):
    r = metacompile(tmp_path, ": EARLY LATER ;\n: LATER 1 ;\n")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "metacompiled" in r.stdout


def test_unresolved_forward_reference_is_reported(tmp_path):
    r = metacompile(tmp_path, ": EARLY\n  NEVER-DEFINED ;\n")
    assert r.returncode != 0
    assert re.search(r"unit\.fs:2: undefined target word NEVER-DEFINED", r.stdout)


def test_error_names_file_and_line(tmp_path):
    r = metacompile(tmp_path, ": OK1 1 ;\nNO-SUCH-HOST-WORD\n")
    assert r.returncode != 0
    assert "unit.fs:2: undefined in the metacompiler: NO-SUCH-HOST-WORD" in r.stdout


def test_unbalanced_structure_is_an_error(tmp_path):
    r = metacompile(tmp_path, ": BAD IF ;\n")
    assert r.returncode != 0
    assert "unit.fs:1: unbalanced control structure" in r.stdout


def read_lda(path):
    """Blocks of the absolute-loader format, checksums verified."""
    data, mem, pos = path.read_bytes(), {}, 0
    while True:
        assert data[pos] == 1 and data[pos + 1] == 0
        count = data[pos + 2] | data[pos + 3] << 8
        addr = data[pos + 4] | data[pos + 5] << 8
        if count == 6:
            return mem, addr
        block = data[pos:pos + count + 1]
        assert sum(block) % 256 == 0, "checksum"
        for i, b in enumerate(data[pos + 6:pos + count]):
            mem[addr + i] = b
        pos += count + 1


def test_lda_and_map_agree():
    mem, start = read_lda(LDA)
    symbols = {}
    for line in MAP.read_text().splitlines():
        addr, name = line.split(" ", 1)
        symbols.setdefault(name, int(addr, 8))
    assert start == symbols["ENTRY"]
    word = lambda a: mem[a] | mem[a + 1] << 8
    assert 0o000134 in [word(symbols["EXIT"] + 2 * k) for k in range(16)]   # EXIT: NEXT
    assert word(symbols["DOCOL"]) == 0o020627                # CMP SP,#limit
    assert 0o000134 in [word(symbols["DOCOL"] + 2 * k) for k in range(12)]
    assert word(symbols["QUIT"]) == 0o004437                 # JSR IP,@#DOCOL
    assert word(symbols["QUIT"] + 2) == symbols["DOCOL"]
    assert word(0o4) == symbols["STUBS"] + 4 and word(0o6) == 0o340
    assert word(symbols["STUBS"] + 0o10) == 0o004037         # JSR R0,@#TRAPPED
    assert word(symbols["STUBS"] + 0o12) == symbols["TRAPPED"]


def test_map_lists_every_word(forth):
    names = {line.split(" ", 1)[1] for line in MAP.read_text().splitlines()}
    shown = forth.send("WORDS").split()
    assert len(shown) > 300
    assert set(shown) <= names
