"""mk/disk.mk: the working disk is made from the pristine image once and never
overwritten by make; export-blocks writes the image's blocks back as text."""
import os
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PRISTINE = ROOT / "build" / "robot.dsk"


def make(*args):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS")}
    return subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=120)


def test_working_disk_is_created_once_and_never_overwritten(tmp_path):
    work = tmp_path / "local" / "robot.dsk"
    result = make(f"WORK_DSK={work}", str(work))
    assert result.returncode == 0, result.stderr
    assert work.read_bytes() == PRISTINE.read_bytes()
    edited = bytearray(work.read_bytes())
    edited[1020 * 1024:1020 * 1024 + 12] = b"( my block )"
    work.write_bytes(bytes(edited))
    os.utime(PRISTINE)          # a newer pristine image must not replace the user's disk
    result = make(f"WORK_DSK={work}", str(work))
    assert result.returncode == 0, result.stderr
    assert work.read_bytes() == bytes(edited)


def test_export_blocks_of_the_pristine_image_changes_nothing():
    before = {p.name: p.read_bytes() for p in (ROOT / "blocks").glob("*.txt")}
    result = make("export-blocks", f"IMAGE={PRISTINE}", "FROM=1000", "TO=1029")
    assert result.returncode == 0, result.stderr
    assert result.stdout.count("unchanged") == 14
    assert "blank, not exported: 1013-1019, 1021-1029" in result.stdout
    assert {p.name: p.read_bytes() for p in (ROOT / "blocks").glob("*.txt")} == before


def test_export_blocks_of_a_missing_image_fails_clearly(tmp_path):
    result = make("export-blocks", f"IMAGE={tmp_path}/none.dsk")
    assert result.returncode != 0
    assert "none.dsk: cannot read the disk image" in result.stderr
