"""`python -m harness disk pack|export`: round trips and bad input (clear message,
non-zero exit, nothing written)."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

from harness.blocks.disk import RL02_BYTES
from tests.cli_in_process import harness_here as harness

ROOT = Path(__file__).resolve().parents[2]


def harness_process(*args):
    """The real `python -m harness ARGV`, for the one test of the start itself."""
    return subprocess.run([sys.executable, "-m", "harness", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=60)


def failed(result, *words):
    assert result.returncode == 1, result
    assert result.stderr.startswith("python -m harness disk"), result.stderr
    for word in words:
        assert word in result.stderr, result.stderr
    return True


def block_dir(directory):
    d = directory / "src"
    d.mkdir()
    (d / "0007.txt").write_text("( seven )\n7 .\n")
    (d / "1000.txt").write_text("( one thousand )\n" + "x" * 64 + "\n")
    (d / "10239.txt").write_text("( the last block )\n")
    (d / "README.md").write_text("not a block\n")
    return d


@pytest.fixture
def src(tmp_path):
    return block_dir(tmp_path)


@pytest.fixture(scope="module")
def packed(tmp_path_factory):
    """block_dir() packed once by `disk pack`, for the tests that only read the
    image (read-only, so none can change it for the next)."""
    directory = tmp_path_factory.mktemp("packed")
    image = directory / "robot.dsk"
    assert harness("disk", "pack", block_dir(directory), image).returncode == 0
    image.chmod(0o444)
    return image


def test_pack_places_block_n_at_byte_1024n_and_blanks_the_rest(src, tmp_path):
    image = tmp_path / "robot.dsk"
    result = harness("disk", "pack", src, image)
    assert result.returncode == 0, result.stderr
    assert "3 blocks" in result.stdout
    data = image.read_bytes()
    assert len(data) == RL02_BYTES == 10240 * 1024
    assert data[7 * 1024:7 * 1024 + 64] == b"( seven )".ljust(64)
    assert data[1000 * 1024 + 64:1000 * 1024 + 128] == b"x" * 64
    assert data[10239 * 1024:10239 * 1024 + 18] == b"( the last block )"
    used = {7, 1000, 10239}
    assert all(data[n * 1024:(n + 1) * 1024] == b" " * 1024
               for n in range(10240) if n not in used)


def test_export_writes_the_non_blank_blocks_in_canonical_form(packed, tmp_path):
    image, out = packed, tmp_path / "out"
    result = harness("disk", "export", image, out)
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in out.iterdir()) == ["0007.txt", "1000.txt", "10239.txt"]
    text = (out / "0007.txt").read_text()
    assert text == "( seven )\n7 .\n" + "\n" * 14
    again = tmp_path / "again.dsk"
    harness("disk", "pack", out, again)
    assert again.read_bytes() == image.read_bytes()


def test_export_range_and_blank_blocks(packed, tmp_path):
    image, out = packed, tmp_path / "out"
    result = harness("disk", "export", image, out, "--from", 999, "--to", 1001)
    assert [p.name for p in out.iterdir()] == ["1000.txt"]
    assert "blank, not exported: 999, 1001" in result.stdout
    harness("disk", "export", image, out, "--from", 999, "--to", 1001, "--all")
    assert (out / "0999.txt").read_text() == "\n" * 16


def test_export_never_overwrites_a_different_file_and_writes_nothing(packed, src):
    image = packed
    (src / "1000.txt").write_text("( edited by hand )\n")
    (src / "0007.txt").unlink()
    result = harness("disk", "export", image, src)
    assert failed(result, "1000.txt: exists and differs from block 1000", "--force")
    assert (src / "1000.txt").read_text() == "( edited by hand )\n"
    assert not (src / "0007.txt").exists(), "nothing is written when one block fails"
    assert harness("disk", "export", image, src, "--force").returncode == 0
    assert (src / "1000.txt").read_text().startswith("( one thousand )\n")
    assert (src / "0007.txt").exists()


def test_export_over_an_identical_file_leaves_it_alone(packed, src):
    image = packed
    result = harness("disk", "export", image, src, "--from", 7, "--to", 7)
    assert result.returncode == 0 and "unchanged" in result.stdout
    assert (src / "0007.txt").read_text() == "( seven )\n7 .\n"


def test_pack_of_a_missing_directory(tmp_path):
    assert failed(harness("disk", "pack", tmp_path / "nowhere", tmp_path / "x.dsk"),
                  "nowhere: no such directory")
    assert not (tmp_path / "x.dsk").exists()


def test_pack_reports_every_bad_file_and_keeps_the_old_image(src, tmp_path):
    image = tmp_path / "robot.dsk"
    image.write_bytes(b"old image")
    (src / "1001.txt").write_text("\tTAB\n")
    (src / "1002.txt").write_text("y" * 65 + "\n")
    (src / "10240.txt").write_text("( too far )\n")
    (src / "12.txt").write_text("( short name )\n")
    (src / "notes.txt").write_text("notes\n")
    result = harness("disk", "pack", src, image)
    assert failed(result, "1001.txt: line 0: column 1: a tab",
                  "1002.txt: line 0: 65 characters",
                  "10240.txt: block 10240 is outside the RL02 disk",
                  "12.txt: block 12 must be named 0012.txt",
                  "notes.txt: not a block file name")
    assert image.read_bytes() == b"old image"
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_export_of_a_missing_or_unreadable_image(tmp_path):
    assert failed(harness("disk", "export", tmp_path / "none.dsk", tmp_path / "o"),
                  "none.dsk: cannot read the disk image: No such file")
    assert failed(harness("disk", "export", tmp_path, tmp_path / "o"),
                  "cannot read the disk image: Is a directory")
    assert not (tmp_path / "o").exists()


def test_export_of_an_image_of_the_wrong_size(tmp_path):
    short = tmp_path / "short.dsk"
    short.write_bytes(b" " * (RL02_BYTES - 1024))
    assert failed(harness("disk", "export", short, tmp_path / "o"),
                  f"{RL02_BYTES - 1024} bytes is not an RL02 image")


@pytest.mark.parametrize("args, words", [
    (("--from", 10240), ["first block 10240 is outside the RL02 disk"]),
    (("--from", 5, "--to", 10240), ["last block 10240 is outside"]),
    (("--from", -1), ["first block -1 is outside"]),
    (("--from", 20, "--to", 10), ["empty range"]),
])
def test_export_of_a_block_out_of_range(packed, tmp_path, args, words):
    image = packed
    assert failed(harness("disk", "export", image, tmp_path / "o", *args), *words)
    assert not (tmp_path / "o").exists()


def test_export_of_a_binary_block_names_it(tmp_path):
    image = tmp_path / "bin.dsk"
    data = bytearray(b" " * RL02_BYTES)
    data[3 * 1024 + 2 * 64] = 0x01
    image.write_bytes(bytes(data))
    assert failed(harness("disk", "export", image, tmp_path / "o"),
                  "block 3: line 2: column 1: byte 0x01")


def test_usage_errors_and_help():
    result = harness_process("disk")
    assert result.returncode == 2 and "ACTION" in result.stderr
    result = harness("--help")
    assert result.returncode == 0 and "disk" in result.stdout
    assert harness("disk", "export", "--help").stdout.count("--force") >= 1


def test_pack_warns_about_lines_that_run_together(tmp_path):
    d = tmp_path / "w"
    d.mkdir()
    (d / "0001.txt").write_text("A" * 64 + "\nB\n")
    result = harness("disk", "pack", d, tmp_path / "w.dsk")
    assert result.returncode == 0
    assert "lines 0 and 1 run together" in result.stderr


def test_written_files_get_ordinary_permissions(src, tmp_path):
    image = tmp_path / "robot.dsk"
    harness("disk", "pack", src, image)
    mask = os.umask(0)
    os.umask(mask)
    assert image.stat().st_mode & 0o777 == 0o666 & ~mask


def test_add_new_fills_only_blank_blocks_and_is_refused_while_held(packed, src, tmp_path):
    """A working disk made by an older version gets the blocks a newer one ships
    (blank there, written on the pristine image); a block the user wrote stays his."""
    import fcntl
    pristine, work = packed, tmp_path / "work.dsk"
    (src / "1000.txt").write_text("( my own block 1000 )\n")
    (src / "0007.txt").unlink()                         # the old version lacked block 7
    assert harness("disk", "pack", src, work).returncode == 0
    with open(work, "rb") as held:                      # a simulator writing it: refused
        fcntl.flock(held, fcntl.LOCK_EX)
        before = work.read_bytes()
        assert failed(harness("disk", "add-new", work, "--from", pristine), "in use", "BYE")
        assert work.read_bytes() == before
    result = harness("disk", "add-new", work, "--from", pristine)
    assert result.returncode == 0, result.stderr
    assert "1 blocks added" in result.stdout and "(7)" in result.stdout
    data = work.read_bytes()
    assert data[7 * 1024:7 * 1024 + 9] == b"( seven )"
    assert data[1000 * 1024:1000 * 1024 + 21] == b"( my own block 1000 )"
    again = harness("disk", "add-new", work, "--from", pristine)
    assert again.returncode == 0 and "nothing to add" in again.stdout


def test_the_console_names_blocks_the_working_disk_lacks(packed, src, tmp_path):
    from harness.machine.console_session import missing_blocks_note
    pristine, work = packed, tmp_path / "work.dsk"
    assert missing_blocks_note(pristine, pristine) is None
    (src / "0007.txt").unlink()
    (src / "10239.txt").unlink()
    assert harness("disk", "pack", src, work).returncode == 0
    note = missing_blocks_note(work, pristine)
    assert "lacks blocks 7, 10239" in note and "disk add-new" in note
