"""Blocks 1000-1012 against the OCR seed and blocks/TRANSCRIPTION.md; `1000 LOAD` read
as LOAD reads it (harness/analysis/forthscan.py) against blocks/KERNEL-WORDS.md."""
import re
from collections import Counter
from pathlib import Path

import pytest

from harness.analysis.forthscan import check_load, words
from harness.blocks.blockfile import fused_line_ends, problems_in_text, split_lines, text_to_block
from harness.blocks.disk import block_ranges

ROOT = Path(__file__).resolve().parents[2]
BLOCKS = ROOT / "blocks"
APPENDIX = range(1000, 1013)
TRANSCRIPTION = (BLOCKS / "TRANSCRIPTION.md").read_text()


def seed_blocks():
    """{n: OCR text} from the verbatim appendix (markdown fences dropped)."""
    found, current = {}, None
    for line in (BLOCKS / "ocr" / "appendix.txt").read_text().split("\n"):
        match = re.match(r"^BLOCK (\d{4})\s*$", line)
        if match:
            current = int(match.group(1))
            found[current] = []
        elif current is not None and not line.strip().startswith("```"):
            found[current].append(line)
    return {n: " ".join(lines) for n, lines in found.items()}


def project_lines(n):
    return split_lines((BLOCKS / f"{n}.txt").read_text())


def rows():
    """(block, first line, last line, seed text or '', project text, reason)."""
    found = []
    cell = r"(?:`([^`]*)`|\(none\))"
    pattern = re.compile(rf"^\| (\d{{4}}) \| (\d+)(?:-(\d+))? \| {cell} \| {cell} \| (.+) \|$",
                         re.M)
    for m in pattern.finditer(TRANSCRIPTION):
        first = int(m.group(2))
        found.append((int(m.group(1)), first, int(m.group(3) or first),
                      m.group(4) or "", m.group(5) or "", m.group(6)))
    return found


def kernel_words(section):
    text = (BLOCKS / "KERNEL-WORDS.md").read_text().split(f"## {section}", 1)[1]
    text = text.split("\n## ", 1)[0]
    return re.findall(r"^\| `([^`]+)` \|", text, re.M)


def packed(numbers):
    return {n: text_to_block((BLOCKS / f"{n}.txt").read_text(), f"{n}.txt") for n in numbers}


def normal(text):
    return " ".join(text.split())


def test_every_block_file_is_well_formed_16_lines():
    for n in list(APPENDIX) + [1020]:
        text = (BLOCKS / f"{n}.txt").read_text()
        assert problems_in_text(text, f"{n}.txt") == []
        assert len(split_lines(text)) == 16, f"{n}.txt has not 16 lines"
        assert fused_line_ends(text_to_block(text)) == [], f"{n}.txt: lines run together"


def test_line_0_of_each_block_is_a_title_comment():
    for n in list(APPENDIX) + [1020]:
        title = project_lines(n)[0]
        assert title.startswith("( ") and title.rstrip().endswith(")"), (n, title)
    assert "LPR 11/21/26)" in project_lines(1020)[0]


def test_1000_load_chains_through_1012_and_stops_there():
    blocks = packed(APPENDIX)
    for n in APPENDIX:
        last = words(blocks[n], n)[-1].text
        assert last == ("-->" if n < 1012 else ";S"), f"block {n} ends with {last}"
    loaded, _defined, _problems = check_load(blocks, 1000, kernel_words("FORTH vocabulary"),
                                             kernel_words("ASSEMBLER vocabulary"))
    assert loaded == list(APPENDIX)


def test_every_word_is_defined_earlier_or_by_the_kernel():
    forth, asm = kernel_words("FORTH vocabulary"), kernel_words("ASSEMBLER vocabulary")
    assert len(forth) > 30 and len(asm) > 30
    _loaded, defined, problems = check_load(packed(APPENDIX), 1000, forth, asm)
    assert problems == []
    for name in ("Desire.Pos", "0-Vel", "Stop?", "Change.Speed?", "Interrupt.Servo",
                 "Abs.Move.Single", "Rel.Move", "Set.Up.Robot", "Move.Complete?"):
        assert name in defined
    assert len(defined) == len(set(defined)) == 40
    _loaded, demo, problems = check_load(packed([1020]), 1020, forth, asm, defined)
    assert problems == [] and "Demo" in demo


def test_the_kernel_word_list_says_exactly_where_each_word_is_used():
    """The list is what the blocks need, nothing more, and its "used in" column is true."""
    used = {"(": set(APPENDIX) | {1020}}
    for n, block in packed(list(APPENDIX) + [1020]).items():
        for word in words(block, n):
            used.setdefault(word.text.upper(), set()).add(n)
    text = (BLOCKS / "KERNEL-WORDS.md").read_text()
    table = re.findall(r"^\| `([^`]+)` \| [^|]+? \| ([^|]+?) \|", text, re.M)
    assert len(table) == len(kernel_words("FORTH vocabulary") +
                             kernel_words("ASSEMBLER vocabulary"))
    for word, where in table:
        assert word.upper() in used, f"{word} is listed but never used"
        assert where == block_ranges(used[word.upper()]), word


@pytest.mark.parametrize("block, old, new, expected", [
    (1011, "4000O 0-Vel 6 + ! ;", "4000O 0-Vel 6 + !", ": inside the definition opened"),
    (1009, "1SET", "ISET", "ISET is not defined"),
    (1003, "CMP,", "CMP.", "CMP. is not defined"),
    (1001, "RP )+", "RP)+", "RP)+ is not defined"),
    (1002, "-->", "   ", "the definition of Stop? never ends"),
    (1006, "THEN,", "     ", "IF, not closed before ;"),
    (1008, "Int.)", "Int. ", "Interrupt.Servo is not defined"),
    (1010, "Abs.Move.Single -1", "Abs.Mov.Single -1", "Abs.Mov.Single is not defined"),
])
def test_the_load_check_catches_the_ocr_damage(block, old, new, expected):
    """Putting one kind of OCR damage back makes the check fail, with the place."""
    blocks = packed(APPENDIX)
    text = (BLOCKS / f"{block}.txt").read_text()
    assert old in text
    blocks[block] = text_to_block(text.replace(old, new, 1))
    _loaded, _defined, problems = check_load(blocks, 1000, kernel_words("FORTH vocabulary"),
                                             kernel_words("ASSEMBLER vocabulary"))
    assert any(expected in p for p in problems), problems


def test_assembler_words_only_count_inside_assembler():
    blocks = packed(APPENDIX)
    text = (BLOCKS / "1009.txt").read_text().replace("CntOut ! CntIn @", "CntOut ! T @ ")
    blocks[1009] = text_to_block(text)
    _l, _d, problems = check_load(blocks, 1000, kernel_words("FORTH vocabulary"),
                                  kernel_words("ASSEMBLER vocabulary"))
    assert problems == ["block 1009 line 3: T is not defined "
                        "(an assembler word outside ASSEMBLER)"]


def test_transcription_has_a_section_for_every_block():
    for n in APPENDIX:
        assert f"### Block {n}" in TRANSCRIPTION


def test_each_row_quotes_the_seed_and_the_project_exactly():
    seeds = seed_blocks()
    table = rows()
    assert len(table) > 100
    for block, first, last, seed, project, reason in table:
        assert seed == "" or normal(seed) in normal(seeds[block]), (block, seed)
        lines = project_lines(block)[first:last + 1]
        assert normal(project) in normal(" ".join(lines)), (block, first, project)
        assert re.match(r"^[CSDIYOL;EMNWP](, [CSDIYOL;EMNWP])*( and [CSDIYOL;EMNWP])?(:|$)",
                        reason), (block, reason)


def test_the_rows_account_for_every_difference():
    """seed words - rows' seed words + rows' project words == project words."""
    seeds = seed_blocks()
    table = rows()
    for n in APPENDIX:
        expected = Counter(seeds[n].split())
        for block, _f, _l, seed, project, _r in table:
            if block == n:
                expected.subtract(seed.split())
                expected.update(project.split())
        actual = Counter(" ".join(project_lines(n)).split())
        expected = +expected                     # drop zero counts
        assert expected == actual, (n, expected - actual, actual - expected)


def test_the_seed_is_the_papers_appendix():
    seeds = seed_blocks()
    assert sorted(seeds) == list(APPENDIX)
    assert "\u0422" in seeds[1002], "the seed is kept verbatim, OCR damage included"


def code_by_line(lines):
    """The words of each line outside comments; a comment may span lines."""
    found, inside = [], False
    for line in lines:
        words = []
        for word in line.split():
            if inside:
                inside = not word.endswith(")")
            elif word == "(":
                inside = True
            else:
                words.append(word)
        found.append(words)
    return found


def test_each_code_line_is_in_the_seed_in_its_order():
    """The word counts cannot see a reordering (1001's Save-Regs: `W MOV, (Save W)
    RP -)` printed, `RP -) W MOV,` loaded). Each project line's code words, but
    those its rows insert, must stand in the seed in that order, once the line's
    rows are applied to the seed: a word moved without a row fails."""
    seeds = seed_blocks()
    table = rows()
    for n in APPENDIX:
        for k, code in enumerate(code_by_line(project_lines(n))):
            seed, inserted = normal(seeds[n]), []
            for block, first, last, old, new, _r in table:
                if block == n and first <= k <= last:
                    if old:
                        seed = seed.replace(normal(old), normal(new))
                    else:
                        inserted += new.split()
            code = [w for w in code if w not in inserted]
            seed_code = " ".join(w for line in code_by_line([seed]) for w in line)
            assert not code or f" {' '.join(code)} " in f" {seed_code} ", (n, k, code)
