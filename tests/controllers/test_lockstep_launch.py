"""`make run CONTROLLERS=4` (python -m harness controllers launch): the five machines with
the 11/23's console in front; an 11/03's console reached from another terminal; a
killed 11/03 reported at the 11/23's console within a second, the others going on,
and the launcher leaving cleanly at BYE."""
import json
import os
import signal
import sys
import time
import urllib.request

import pexpect
import pytest

from harness.machine import pty_child
from harness.machine.build import KERNEL_1103, PRISTINE_DISK, ROOT, fresh_disk
from harness.machine.pty_spawn import Spawn

pytestmark = pytest.mark.skipif(not KERNEL_1103.exists(), reason="no build/kernel-1103.lda")


def harness(*args, cwd=ROOT):
    child = Spawn(sys.executable, ["-m", "harness", *args], cwd=str(cwd),
                  encoding="latin-1", timeout=60, dimensions=(24, 200))
    child.delaybeforesend = None
    return child


@pytest.fixture
def five(tmp_path):
    disk = fresh_disk(tmp_path, "main.dsk", source=PRISTINE_DISK)
    child = harness("controllers", "launch", "--fast", "--no-boot-lines", "--busy-wait", "2",
                    "--disk", str(disk), "--session-dir", str(tmp_path / "session"))
    pids = {}
    for _ in range(4):
        child.expect(r"11/03 (\w): pid (\d+); its console: python -m harness controllers console")
        pids[child.match.group(1)] = int(child.match.group(2))
    child.expect(" ok\r\n")
    yield child, pids, tmp_path / "session"
    if child.isalive():
        child.close(force=True)


def launch_booted(tmp_path):
    """`controllers launch` typing the 11/03s' boot lines, once their four servos
    have said so in their logs: the child, the 11/03s' pids, the session folder."""
    disk = fresh_disk(tmp_path, "main.dsk", source=PRISTINE_DISK)
    session = tmp_path / "session"
    child = harness("controllers", "launch", "--fast", "--busy-wait", "5", "--disk", str(disk),
                    "--session-dir", str(session))
    child.timeout = 120
    pids = {}
    for _ in range(4):
        child.expect(r"11/03 (\w): pid (\d+)")
        pids[child.match.group(1)] = int(child.match.group(2))
    child.expect(" ok\r\n")
    deadline = time.monotonic() + 120
    while not all("servo on axis" in (session / f"{a}.log").read_text("latin-1")
                  for a in "xyzt"):
        assert time.monotonic() < deadline, "the 11/03s did not boot their servos"
        time.sleep(0.2)
    return child, pids, session


def leave(child):
    child.send("BYE\r")
    child.expect("Bye.")
    child.expect(pexpect.EOF)
    pty_child.close(child)                  # it has exited: no pexpect pause
    return child.exitstatus


def test_a_killed_11_03_is_reported_within_a_second_and_the_rest_goes_on(five):
    child, pids, _ = five
    child.send("1 2 + .\r")
    child.expect("3  ok")
    killed = time.monotonic()
    os.kill(pids["y"], signal.SIGKILL)
    child.expect("11/03 axis y stopped: its simulator is gone", timeout=5)
    assert time.monotonic() - killed < 1.0
    child.send("61416 @ .\r")                          # the 11/23's link y CSR: PEER LOST
    child.expect(r"61416 @ \. (-?\d+)  ok")
    assert int(child.match.group(1)) & 0o400
    assert leave(child) == 0
    main_log = (five[2] / "main.log").read_text(encoding="latin-1")   # the page's 11/23 panel
    assert "1 2 + . 3  ok" in main_log and "61416 @ ." in main_log


def test_an_11_03_console_is_reached_from_another_terminal(five):
    child, _, session = five
    other = harness("controllers", "console", "z", "--session-dir", str(session))
    other.expect(" ok")                                # its boot, replayed
    other.send("6 7 * .\r")
    other.expect("42  ok")
    other.send("\x1d")                                 # ^] leaves it running
    other.expect("left the console of z")
    other.expect(pexpect.EOF)
    assert leave(child) == 0
    assert "6 7 * . 42  ok" in (session / "z.log").read_text(encoding="latin-1")


def test_the_lab_page_shows_the_five_machines(tmp_path):
    disk = fresh_disk(tmp_path, "main.dsk", source=PRISTINE_DISK)
    child = harness("controllers", "launch", "--fast", "--no-boot-lines", "--lab", "--busy-wait",
                    "2", "--disk", str(disk), "--session-dir", str(tmp_path / "session"))
    child.expect(r"the five machines' page: (http://127\.0\.0\.1:\d+/\?token=[\w-]+)")
    url = child.match.group(1)
    child.expect(" ok\r\n")
    base, token = url.split("/?token=")
    deadline = time.monotonic() + 30
    while True:                                   # the first status comes at 0.1 s simulated
        with urllib.request.urlopen(f"{base}/status?token={token}", timeout=10) as r:
            view = json.load(r)
        if view["started"] or time.monotonic() > deadline:
            break
        time.sleep(0.1)
    assert [m["state"] for m in view["machines"]] == ["running"] * 5
    assert [a["axis"] for a in view["servo"]] == list("XYZT")
    assert any(" ok" in m["console"] for m in view["machines"] if m["name"] == "x")
    assert leave(child) == 0
