"""harness.blocks: blocks/ text <-> RL02 image, checked by gforth and by the FORTH.

Pack a folder of block files, boot the emulator on the image and LOAD from it,
edit at the terminal, export the image back to text: the round trip is exact."""
import subprocess
import sys

import pytest

from harness import blocks
from harness.machine import Machine, RL02_BYTES, ROOT


def write(folder, name, text):
    folder.mkdir(exist_ok=True)
    (folder / name).write_text(text)


def run_tool(*args):
    return subprocess.run([sys.executable, "-m", "harness.blocks", *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT, timeout=60)


def test_pack_boot_edit_export_round_trip(tmp_path):
    src = tmp_path / "blocks"
    write(src, "0300.fb", "( packed block )\n: PACKED ( -- n ) 300 ;\n")
    write(src, "0301.fb", "( second )\n")
    image = tmp_path / "robot.dsk"
    r = run_tool("pack", src, image)
    assert r.returncode == 0, r.stderr
    assert image.stat().st_size == RL02_BYTES
    with Machine(disk=image) as m:
        assert m.send("300 LOAD PACKED .").split() == ["300"]
        m.send("EDITOR 301 LIST 1 P : EDITED ( -- n ) 301 ;")
        m.send("FLUSH")
    out = tmp_path / "exported"
    r = run_tool("export", image, out)
    assert r.returncode == 0, r.stderr
    assert sorted(p.name for p in out.iterdir()) == ["0300.fb", "0301.fb"]
    assert (out / "0300.fb").read_text() == (src / "0300.fb").read_text()
    assert (out / "0301.fb").read_text() == "( second )\n: EDITED ( -- n ) 301 ;\n"
    # gforth sees the same text at the same place
    g = subprocess.run(["gforth", "-e", f"use {image} 300 list bye"],
                       capture_output=True, text=True, timeout=30)
    assert " 1 : PACKED ( -- n ) 300 ;" in g.stdout


@pytest.mark.parametrize("name, text, message", [
    ("0001.fb", "x" * 65 + "\n", "0001.fb:1: 65 characters"),
    ("0002.fb", "ok\n" * 17, "17 lines"),
    ("0003.fb", "tab\there\n", "not printable"),
    ("10240.fb", "past the end\n", "NNNN.fb"),
])
def test_bad_block_text_is_refused_and_no_image_is_written(tmp_path, name, text, message):
    src = tmp_path / "blocks"
    write(src, name, text)
    image = tmp_path / "robot.dsk"
    r = run_tool("pack", src, image)
    assert r.returncode == 1 and message in r.stderr
    assert not image.exists()


def test_export_never_deletes_a_block_file(tmp_path):
    src = tmp_path / "blocks"
    write(src, "0005.fb", "( five )\n")
    write(src, "0006.fb", "( six )\n")
    image = tmp_path / "robot.dsk"
    blocks.pack(src, image)
    with Machine(disk=image) as m:
        m.send("EDITOR 6 WIPE FLUSH")            # blank on the image now
    r = run_tool("export", image, src, 5, 6)
    assert r.returncode == 0, r.stderr
    assert "block 6 is blank on the image; 0006.fb left as it was" in r.stdout
    assert (src / "0006.fb").read_text() == "( six )\n"


def test_working_copy_is_never_overwritten(tmp_path):
    pristine, copy = tmp_path / "pristine.dsk", tmp_path / "local" / "robot.dsk"
    blocks.pack(tmp_path, pristine)              # no .fb files: a blank disk
    assert blocks.working_copy(pristine, copy)
    with open(copy, "r+b") as f:
        f.write(b"user's work")
    assert not blocks.working_copy(pristine, copy)
    assert copy.read_bytes()[:11] == b"user's work"
