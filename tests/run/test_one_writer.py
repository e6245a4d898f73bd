"""One simulator writes a disk image at a time (issue 16, item 8): the RL's
ATTACH takes an exclusive lock (pdp11-devices/simh/rl_one_writer.c), so a second
simulator on the same image is refused naming the holder, through every entry
point, or attaches it read-only when asked; the lock dies with its process."""
import re
import shutil
import subprocess
import time

import pytest

from harness.cli import main
from harness.machine import pty_child, simh
from harness.machine.machine import IDLE_PACE
from harness.machine.scripted_machine import ScriptError, ScriptedMachine
from tests.run.common import (IDLE_SPEED, PRISTINE, ROOT, SIMULATOR, ended, harness_console,
                              needs_build, spawn)

pytestmark = needs_build

BLOCK = 300


def boot(disk, tmp_path, read_only=False, name="boot.ini"):
    """build/pdp11 booting the FORTH on `disk`, at its prompt (idling as the pty
    Machine does, not racing a host core while it holds the disk)."""
    ini = tmp_path / name
    ini.write_text(simh.boot_script(disk, setup=IDLE_PACE, read_only=read_only))
    child = spawn(SIMULATOR, ini)
    child.expect(rb"blocks 0-\d+\.\r\n ok\r\n")
    return child


def holding(directory):
    """A disk image a running simulator writes: (disk, that simulator)."""
    disk = directory / "robot.dsk"
    shutil.copyfile(PRISTINE, disk)
    return disk, boot(disk, directory, name="first.ini")


@pytest.fixture(scope="module")
def held(tmp_path_factory):
    """holding(), one for the tests that only try the held disk (the lock is the
    same whichever test came before)."""
    disk, first = holding(tmp_path_factory.mktemp("held"))
    yield disk, first
    pty_child.kill(first)


@pytest.fixture
def held_alone(tmp_path):
    """holding(), for a test that ends the holder."""
    disk, first = holding(tmp_path)
    yield disk, first
    pty_child.kill(first)


def holder_named(text, first):
    return re.search(rf"in use by pid {first.pid} since \d{{4}}-\d\d-\d\d "
                     r"\d\d:\d\d:\d\d UTC", text)


def test_a_second_simulator_by_hand_is_refused_naming_the_holder(held, tmp_path):
    disk, first = held
    ini = tmp_path / "second.ini"
    ini.write_text(simh.boot_script(disk))
    second = subprocess.run([str(SIMULATOR), str(ini)], capture_output=True, text=True,
                            timeout=30, cwd=ROOT, stdin=subprocess.DEVNULL)
    assert second.returncode == simh.DISK_HELD
    assert holder_named(second.stdout, first), second.stdout
    assert "PDP-11/23 FORTH" not in second.stdout         # no diskless boot


def test_a_second_unit_of_the_same_simulator_is_refused_too(held):
    disk, first = held
    first.send(b"\x05")
    first.expect(b"sim> ")
    first.send(f"attach rl1 {disk}\r".encode())
    first.expect(b"sim> ")
    assert b"is in use by" in first.before
    first.send(b"show rl1\r")
    first.expect(b"sim> ")
    assert b"not attached" in first.before
    first.send(b"cont\r")                                 # holding on, as it was


def test_read_only_beside_the_writer_reports_a_write_as_an_error(held, tmp_path):
    """ATTACH -R: the FORTH's FLUSH fails and says so, the block stays UPDATEd, QUIT
    is refused naming it, QUIT -F leaves without it; the image is unchanged."""
    disk, _ = held
    before = disk.read_bytes()
    reader = boot(disk, tmp_path, read_only=True)
    reader.send(f"{BLOCK} BLOCK 1024 90 FILL UPDATE FLUSH\r".encode())
    reader.expect(rb"RL0 block 300 write not ready: drive=\d+ write-locked\r\n"
                  rb"Error: block write error: FLUSH")
    reader.send(b"\x05")
    reader.expect(b"sim> ")
    reader.send(b"quit\r")
    reader.expect(rb"QUIT refused: block\(s\) 300 UPDATEd and not written .* QUIT -F to "
                  rb"leave without them\r\nsim> ")
    reader.send(b"quit -f\r")
    reader.expect(rb"QUIT -F: leaving without block\(s\) 300: UPDATEd, NOT SAVED")
    assert ended(reader) == simh.LEFT_WITHOUT_BLOCKS
    assert disk.read_bytes() == before


def test_the_lock_dies_with_a_killed_simulator(held_alone, tmp_path):
    """kill -9 leaves no stale lock (flock ends with the process): the next
    simulator attaches; the holder file left behind is rewritten."""
    disk, first = held_alone
    pty_child.kill(first)                                   # SIGKILL
    second = boot(disk, tmp_path, name="second.ini")
    assert f"pid {second.pid} since" in (tmp_path / "robot.dsk.lock").read_text()
    second.send(b"\x05")
    second.expect(b"sim> ")
    second.send(b"quit\r")
    assert ended(second) == 0
    assert not (tmp_path / "robot.dsk.lock").exists()       # removed at DETACH


def test_the_console_says_it_in_one_line_and_exits_1(held, capsys):
    disk, first = held
    assert main(["console", "--fast", "--disk", str(disk)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and holder_named(err[0], first), err


def test_the_console_read_only_boots_beside_the_writer(held):
    disk, _ = held
    child = harness_console("--fast", *IDLE_SPEED, "--read-only", "--disk", disk)
    child.expect(rb"RL: unit is read only")
    child.expect(rb"blocks 0-\d+\.\r\n ok\r\n")
    child.send(b"BYE\r")
    assert ended(child) == 0                  # nothing UPDATEd: nothing lost


def test_the_lab_says_it_in_one_line_and_exits_1(held, capsys):
    disk, first = held
    assert main(["lab", "--port", "0", "--disk", str(disk)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and holder_named(err[0], first), err


def test_a_scripted_run_says_it_in_one_line_and_exits_1(held, tmp_path, capsys):
    disk, first = held
    script = tmp_path / "s.forth"
    script.write_text("1 2 + .\n")
    assert main(["run", str(script), "--disk", str(disk)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and holder_named(err[0], first), err


def test_the_scripted_machine_on_a_held_disk_names_the_holder(held):
    """The simulator's own refusal (a second writer that got past the harness's
    check) ends the boot; the scripted machine raises it as one line."""
    disk, first = held
    with pytest.raises(ScriptError) as refused:
        ScriptedMachine(disk.name, cwd=disk.parent)
    assert holder_named(str(refused.value), first)
    assert "\n" not in str(refused.value)


def test_the_bare_boot_script_paces_its_idle_prompt(tmp_path):
    """build/robot.ini (what a SIMH user runs by hand): half a wall second at the
    prompt is about half a simulated second (SET CPU IDLE), not the hundred or so
    the FORTH's KEY loop would count at full speed; and `-r` attaches the disk
    read-only."""
    disk = tmp_path / "robot.dsk"
    shutil.copyfile(PRISTINE, disk)
    ini = tmp_path / "robot.ini"
    ini.write_text((ROOT / "build" / "robot.ini").read_text()
                   .replace("local/robot.dsk", str(disk)))
    child = spawn(SIMULATOR, ini)
    child.expect(rb" ok\r\n")
    start = time.monotonic()
    time.sleep(0.5)
    child.send(b"\x05")
    child.expect(b"sim> ")
    wall = time.monotonic() - start
    child.send(b"show clk state\r")
    child.expect(rb"time=([\d.]+)s")
    simulated = float(child.match.group(1))
    child.send(b"quit\r")
    assert ended(child) == 0
    assert simulated < wall + 5, f"{simulated} simulated s in {wall:.1f} wall s"
    reader = spawn(SIMULATOR, ini, "-r")
    reader.expect(rb"RL: unit is read only")
    pty_child.kill(reader)
