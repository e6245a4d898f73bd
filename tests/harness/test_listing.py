"""`listing`: blocks 1000-1012 beside what each line laid down in memory."""
import re
import subprocess
import sys

import pytest

from harness.analysis.listing import make_listing, thread_operands
from harness.blocks.blockfile import BLOCK_BYTES, text_to_block
from harness.machine.build import fresh_disk
from tests.conftest import ROOT


@pytest.fixture(scope="module")
def listing():
    return make_listing()


@pytest.fixture(scope="module")
def text(listing):
    """The listing as it is printed, formatted once for the tests that read it."""
    return listing.format()


def test_every_line_of_every_block_is_listed(text):
    for blk in range(1000, 1013):
        source = (ROOT / "blocks" / f"{blk}.txt").read_text().splitlines()
        section = text.split(f"Block {blk}\n", 1)[1].split("\nBlock ", 1)[0]
        listed = [l for l in section.splitlines() if re.match(r"^[ 1]\d \S?", l)]
        assert len(listed) == 16, blk
        for n, line in enumerate(source):
            assert listed[n].startswith(f"{n:2} {line.rstrip()}".rstrip()), (blk, n)


def test_interrupt_servo_is_assembled_by_block_1008_line_2(listing):
    """The macros of 1001-1007 compile calls; CODE Interrupt.Servo runs them."""
    spans = listing.spans[(1008, 2)]
    code = [row for s in spans if s.code for row in s.disassembly]
    texts = [t for _, _, t in code]
    assert texts[:3] == ["MOV R0,-(SP)", "MOV R1,-(SP)", "MOV R2,-(SP)"]   # Save-Regs
    assert texts[-4:] == ["MOV (SP)+,R2", "MOV (SP)+,R1", "MOV (SP)+,R0", "RTI"]
    assert "MOV R0,@#167770" in texts           # CntOut @# R0 MOV, selects the axis
    # each disassembled instruction's words follow one another with no gap
    for (a, words, _), (b, _, _) in zip(code, code[1:]):
        assert b == a + 2 * len(words)


def test_macro_blocks_hold_threaded_code_only(listing):
    for blk in range(1001, 1008):
        for (b, _), spans in listing.spans.items():
            if b == blk:
                assert not any(s.code for s in spans), blk
    mov = [s for s in listing.spans[(1002, 5)] if s.words]
    assert [listing.names.get(w) for w in mov[-1].words] == ["MOV,"]


def test_headers_and_names_of_new_words(listing):
    headers = [s.header for ss in listing.spans.values() for s in ss if s.header]
    assert headers[:2] == ["Desire.Pos", "State"]
    assert "Interrupt.Servo" in headers and "Move.Complete?" in headers
    assert "Read.Counter" in headers                  # block 1009's
    assert "Abs.Move.Single" in listing.names.values()


@pytest.mark.parametrize("blocks", ["1013", "1012-1000", "10x", "1019-1020"])
def test_cli_bad_blocks_is_a_usage_error(tmp_path, cli, blocks):
    out = tmp_path / "x.lst"
    status, _, err = cli("listing", "--blocks", blocks, "--out", out)
    assert status == 2
    assert err.startswith("usage: python -m harness listing")
    assert "argument --blocks" in err
    assert not out.exists()


def test_operands_are_named(text):
    assert "MOV Desire.Pos(R1),R2" in text             # an ARRAY's body
    assert "MOV R0,@#CntOut  ; DRV11 CSR" in text      # the constant the source used
    assert "CMP R2,@#Range" in text                    # a VAR's body
    assert "MOV 0-Vel(R1),VelOut(R1)  ; AAV11 DAC x" in text


def test_assembler_words_named_and_headers_not(listing, text):
    words = [w for s in listing.spans[(1002, 7)] for w in s.words]   # W Desire.Pos T I) MOV,
    assert [listing.names.get(w) for w in words] == ["W", "Desire.Pos", "T", "I)", "MOV,"]
    section = text.split("Block 1002\n", 1)[1]
    header_row = [l for l in section.splitlines() if l.startswith("     ")][1]
    assert header_row.split()[-1] == "DOCOL"      # the code field's handler, nothing else


@pytest.fixture(scope="module")
def beyond(tmp_path_factory):
    """The command line's own start, a real `python -m harness listing --blocks
    1030-1031 --out FILE` (the other tests call it in this process, the `cli`
    fixture): (its result, the listing it wrote)."""
    out = tmp_path_factory.mktemp("beyond") / "b.lst"
    r = subprocess.run([sys.executable, "-m", "harness", "listing", "--blocks", "1030-1031",
                        "--out", str(out)], cwd=ROOT, capture_output=True, text=True)
    return r, out.read_text() if out.exists() else ""


def test_cli_writes_the_blocks_asked_for(beyond):
    r, text = beyond
    assert r.returncode == 0, r.stderr
    assert text.startswith("Block 1030\n")
    assert "Block 1012" not in text           # loaded first (1000 LOAD), not listed


def test_blocks_beyond_the_appendix_are_loaded_by_chain(beyond):
    _, text = beyond
    assert "Block 1031\n" in text and "header of Ramp.Servo" in text


def test_blocks_that_need_others_first_say_so_and_take_load(tmp_path, cli):
    out = tmp_path / "l.lst"
    status, _, err = cli("listing", "--blocks", "1060", "--out", out)
    assert status == 1 and "undefined word: Via" in err and "--load N" in err
    status, _, err = cli("listing", "--blocks", "1060", "--load", "1040", "--out", out)
    assert status == 0, err
    assert out.read_text().startswith("Block 1060\n")


def test_cli_lists_a_block_of_the_users_own_disk(tmp_path, cli):
    """--disk: a block the user wrote (here 1100, packed into a copy of the disk)
    listed beside what it compiled; the image itself is only read."""
    disk = fresh_disk(tmp_path, "mine.dsk")
    with open(disk, "r+b") as image:
        image.seek(1100 * BLOCK_BYTES)
        image.write(text_to_block(": Twice ( n -- 2n )   DUP + ;\n"))
    before = disk.read_bytes()
    status, out, err = cli("listing", "--disk", disk, "--blocks", "1100")
    assert status == 0, err
    assert "header of Twice" in out and "DUP" in out
    assert disk.read_bytes() == before
    status, _, err = cli("listing", "--blocks", "1100")           # not on the pristine disk
    assert status == 2 and "argument --blocks" in err


def test_thread_operands_name_nothing():
    """Issue 18: a thread's inline cells are data: a literal that happens to equal
    a kernel address (1024 = DOCOL), a string's bytes, a branch's target."""
    sym = {"DOCOL": 0o2000, "(LIT)": 0o2122, '(ABORT")': 0o12232, "?BRANCH": 0o2202,
           "EXIT": 0o2060, "(DOES>)": 0o24524}
    cfa = 0o50000
    thread = [0o4437, 0o2000,                    # JSR R4,@#DOCOL
              0o2122, 0o2000,                    # (LIT) 1024
              0o2202, 0o50024,                   # ?BRANCH past the EXIT below
              0o12232, 3 | ord("+") << 8, ord("F") | ord("I") << 8,   # (ABORT") "+FI"
              0o2060,                            # EXIT: a branch goes past it
              0o2060,                            # EXIT: the end
              0o2122]                            # beyond: not this word's
    words = {cfa + 2 * i: w for i, w in enumerate(thread)}
    inline = thread_operands(words, cfa, sym)
    assert inline == {cfa + 6: "lit", cfa + 10: "", cfa + 14: "", cfa + 16: ""}
    assert thread_operands({cfa: 0o4237, cfa + 2: 0o2026}, cfa, sym) == {}   # a CREATE word


def test_asn_listing_names_no_data(tmp_path):
    text = make_listing(1070, 1078).format()
    assert "(LIT) DOCOL" not in text                # 1024 BLANK in Save.Net
    assert "(LIT) ' Interrupt.Servo" in text        # ' Interrupt.Servo: an xt, named so
    assert "header of .Net\n" in text
    assert not re.search(r'\(ABORT"\) \S', text) and not re.search(r'\(\."\) \S', text)
