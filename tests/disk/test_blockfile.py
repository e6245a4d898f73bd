"""harness.blocks.blockfile: text <-> 1024-byte blocks, and the validation messages."""
import random

import pytest

from harness.blocks.blockfile import (BLOCK_BYTES, BlockError, block_to_text, fused_line_ends,
                               is_blank, problems_in_text, text_to_block)


def canonical(lines):
    lines = [line.rstrip(" ") for line in lines] + [""] * (16 - len(lines))
    return "".join(line + "\n" for line in lines)


def test_lines_are_padded_to_64_and_stored_in_order():
    block = text_to_block("( title )\n: X 1 ;\n")
    assert len(block) == BLOCK_BYTES
    assert block[:64] == b"( title )".ljust(64)
    assert block[64:128] == b": X 1 ;".ljust(64)
    assert block[128:] == b" " * (BLOCK_BYTES - 128)


def test_round_trip_of_canonical_text_is_exact():
    rng = random.Random(1983)
    printable = [chr(c) for c in range(32, 127)]
    for _ in range(200):
        lines = ["".join(rng.choice(printable) for _ in range(rng.randint(0, 64)))
                 for _ in range(16)]
        text = canonical(lines)
        assert block_to_text(text_to_block(text)) == text
        block = text_to_block(text)
        assert text_to_block(block_to_text(block)) == block


def test_unpack_strips_trailing_spaces_and_always_gives_16_lines():
    text = block_to_text(text_to_block("a   \n\n  b\n"))
    assert text.split("\n")[:-1] == ["a", "", "  b"] + [""] * 13


def test_a_file_without_final_newline_is_the_same_block():
    assert text_to_block("x\ny") == text_to_block("x\ny\n")


def test_exactly_64_characters_and_16_lines_are_accepted():
    text = "\n".join(["#" * 64] * 16) + "\n"
    assert text_to_block(text) == b"#" * 1024


@pytest.mark.parametrize("text, line, words", [
    ("ok\n" + "x" * 65 + "\n", 1, ["65 characters", "holds 64", "'x'"]),
    ("\n" * 16 + "extra\n", 16, ["17 lines", "holds 16"]),
    ("( caf\u00e9 )\n", 0, ["column 6", "non-ASCII", "U+00E9"]),
    ("\u0422 R0 MOV,\n", 0, ["column 1", "U+0422"]),
    ("ok\nok\n\tDUP\n", 2, ["column 1", "tab"]),
    ("DUP\r\n", 0, ["carriage return"]),
    ("DUP\x07\n", 0, ["control character 0x07"]),
])
def test_each_problem_names_the_file_and_line(text, line, words):
    with pytest.raises(BlockError) as caught:
        text_to_block(text, "blocks/1000.txt")
    message = str(caught.value)
    assert f"blocks/1000.txt: line {line}: " in message
    for word in words:
        assert word in message


def test_every_problem_is_reported_not_just_the_first():
    problems = problems_in_text("\tA\nB\u00e9\n" + "C" * 70 + "\n", "f.txt")
    assert [p.line for p in problems] == [0, 1, 2]


def test_blank_blocks_spaces_or_never_written_zeros():
    assert is_blank(b" " * 1024) and is_blank(b"\0" * 1024)
    assert not is_blank(b" " * 1023 + b"x")
    assert block_to_text(b"\0" * 1024) == "\n" * 16


def test_binary_block_is_refused_with_its_line():
    data = bytearray(b" " * 1024)
    data[64 * 5 + 9] = 0x80
    with pytest.raises(BlockError, match=r"block 7: line 5: column 10: byte 0x80"):
        block_to_text(bytes(data), "block 7")


def test_a_full_line_followed_by_a_word_is_detected():
    block = text_to_block("x" * 64 + "\nDUP\n" + " " * 64 + "\n DROP\n")
    assert fused_line_ends(block) == [0]


def test_a_full_line_ending_its_own_comment_does_not_run_into_the_next():
    title = "( " + "t" * 61 + ")"                      # line 0 of blocks 1070-1078
    assert fused_line_ends(text_to_block(title + "\n( next line)\n")) == []
    assert fused_line_ends(text_to_block(".( " + "t" * 60 + ")\nCR\n")) == []
    # a ) with no comment opened before it on its line: reported (a comment begun on
    # an earlier line is not followed back; the warning errs on the side of saying it)
    assert fused_line_ends(text_to_block("x" * 63 + ")\nDUP\n")) == [0]
    assert fused_line_ends(text_to_block("( a\n" + "x" * 63 + ")\nDUP\n")) == [1]
    assert fused_line_ends(text_to_block("(x" + "t" * 61 + ")\nDUP\n")) == [0]
