"""gforth 0.7.3 opens build/robot.dsk as a plain block file and sees the blocks' text:
the RL02 image is block n at byte 1024n, 16 lines of 64 characters."""
import subprocess
from pathlib import Path

from harness.blocks.blockfile import split_lines
from harness.blocks.disk import pack, read_block_dir

ROOT = Path(__file__).resolve().parents[2]
IMAGE = ROOT / "build" / "robot.dsk"
SHOWN = list(range(1000, 1013)) + [1020]


def gforth(code):
    test_the_image_is_packed_from_the_current_blocks()
    result = subprocess.run(["gforth", "-e", f's" {IMAGE}" open-blocks {code} bye'],
                            cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return result.stdout


def expected_lines(n):
    lines = split_lines((ROOT / "blocks" / f"{n}.txt").read_text())
    return lines + [""] * (16 - len(lines))


def test_the_image_is_packed_from_the_current_blocks():
    assert IMAGE.exists(), "build/robot.dsk is missing: run make"
    blocks, _warnings = read_block_dir(ROOT / "blocks")
    assert IMAGE.read_bytes() == pack(blocks), "build/robot.dsk is stale: run make"


def test_1000_list_shows_exactly_the_block_file():
    out = gforth("1000 list").splitlines()
    assert out[0].startswith("Screen 1000")
    listed = out[1:17]
    assert [line[:2].strip() for line in listed] == [str(i) for i in range(16)]
    assert [line[3:3 + 64].rstrip() for line in listed] == expected_lines(1000)


def test_block_returns_every_line_of_every_block():
    show = (": show ( n -- ) block 16 0 do dup i 64 * + 64 -trailing type .\" |\" cr"
            " loop drop ; ")
    out = gforth(show + " ".join(f"{n} show" for n in SHOWN)).splitlines()
    assert len(out) == 16 * len(SHOWN)
    for k, n in enumerate(SHOWN):
        assert out[16 * k:16 * (k + 1)] == [line + "|" for line in expected_lines(n)], n


def test_an_unused_block_is_blank_to_gforth():
    out = gforth(": blank? ( n -- ) block 1024 -trailing nip . ; 0 blank? 10239 blank?")
    assert out.split() == ["0", "0"]
