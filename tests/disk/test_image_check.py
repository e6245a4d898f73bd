"""Disk images are refused when wrong (harness.blocks.disk.check_image), by run, regress and
console alike: one line naming the file and what is wrong, exit status 1, before
the simulator starts."""
import subprocess
import sys

import pytest

from harness import cli
from harness.blocks.disk import RL02_BYTES, DiskError, check_image
from harness.commands import regress

from tests.run.common import ROOT, needs_build


def make(tmp_path, case):
    """A bad image of kind `case`; its path."""
    path = tmp_path / f"{case}.dsk"
    if case == "directory":
        path.mkdir()
    elif case != "missing":
        size = {"empty": 0, "short": 1000, "rl01": RL02_BYTES // 2,
                "long": RL02_BYTES + 1}.get(case, RL02_BYTES)
        with open(path, "wb") as f:
            f.truncate(size)
        path.chmod({"unreadable": 0o000, "locked": 0o444}.get(case, 0o644))
    return path


CASES = [("missing", "no such disk image"),
         ("directory", "not a regular file"),
         ("empty", "empty (0 bytes), not an RL02 image"),
         ("short", "1000 bytes is not an RL02 image"),
         ("rl01", "5242880 bytes is not an RL02 image (10485760 bytes"),
         ("long", "10485761 bytes is not an RL02 image"),
         ("unreadable", "cannot be read"),
         ("locked", "write-locked")]


@pytest.mark.parametrize("case,message", CASES)
def test_check_image_names_the_file_and_the_fault(tmp_path, case, message):
    path = make(tmp_path, case)
    with pytest.raises(DiskError) as err:
        check_image(path)
    assert str(err.value).startswith(f"{path}: ") and message in str(err.value)
    assert "\n" not in str(err.value)


def test_a_good_image_passes_and_a_locked_one_may_be_read(tmp_path):
    check_image(make(tmp_path, "good"))
    check_image(make(tmp_path, "locked"), writable=False)


def refused(capsys, argv, command, path, message):
    """Exit 1 and one line on stderr: the command, the file, what is wrong; nothing
    booted (the check comes first, in the same process)."""
    assert cli.main([str(a) for a in argv]) == 1
    out = capsys.readouterr()
    lines = out.err.splitlines()
    assert len(lines) == 1, out.err
    assert lines[0].startswith(f"python -m harness {command}: error: {path}: "), lines
    assert message in lines[0], lines
    assert "booting" not in out.out
    return True


@needs_build
@pytest.mark.parametrize("case,message", [c for c in CASES if c[0] != "locked"])
def test_run_refuses_a_bad_image_before_booting(tmp_path, capsys, case, message):
    script = tmp_path / "s.script"
    script.write_text("1 .\n")
    path = make(tmp_path, case)
    assert refused(capsys, ["run", script, "--disk", path], "run", path, message)
    assert not (tmp_path / "s.transcript").exists()


@needs_build
def test_run_boots_a_copy_of_a_locked_image(tmp_path):
    """run never writes the image it starts from, so a read-only one is fine."""
    script = tmp_path / "s.script"
    script.write_text("1 .\n")
    result = subprocess.run([sys.executable, "-m", "harness", "run", str(script), "--disk",
                             str(make(tmp_path, "locked"))], cwd=ROOT, capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 0, result.stderr


@pytest.mark.parametrize("case,message", [("empty", "empty (0 bytes)"),
                                          ("locked", "write-locked"),
                                          ("rl01", "not an RL02 image"),
                                          ("missing", "no such disk image")])
def test_console_refuses_a_bad_image_before_booting(tmp_path, capsys, case, message):
    path = make(tmp_path, case)
    assert refused(capsys, ["console", "--fast", "--disk", path], "console", path, message)


def test_regress_checks_the_pristine_image_once_before_any_scenario(tmp_path, capsys,
                                                                   monkeypatch):
    path = make(tmp_path, "empty")
    monkeypatch.setattr(regress, "PRISTINE_DISK", path)
    monkeypatch.setattr(regress.regression, "main", lambda *a: pytest.fail("ran"))
    assert cli.main(["regress"]) == 1
    err = capsys.readouterr().err
    assert err == f"python -m harness regress: error: {path}: empty (0 bytes), not an " \
                  f"RL02 image ({RL02_BYTES} bytes)\n"
