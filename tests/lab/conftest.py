"""Lab tests: a lab server per module (python -m harness lab, at full speed, on a copy
of the pristine disk, on a free port) and one headless Chromium for the session."""
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM, CHROMEDRIVER = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")
ARTIFACTS = ROOT / "build" / "test-artifacts"


class LabServer:
    def __init__(self, tmp):
        disk = tmp / "robot.dsk"
        shutil.copyfile(ROOT / "build" / "robot.dsk", disk)
        self.log = tmp / "lab.log"
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "harness", "lab", "--port", "0", "--speed", "full",
             "--disk", str(disk)], cwd=ROOT, stdout=open(self.log, "w"),
            stderr=subprocess.STDOUT)
        deadline = time.monotonic() + 30
        while not (m := re.search(r"http://127\.0\.0\.1:(\d+)/\?token=(\S+)", self.text())):
            if self.proc.poll() is not None or time.monotonic() > deadline:
                self.proc.kill()
                raise RuntimeError(f"the lab server did not start:\n{self.text()}")
            time.sleep(0.05)
        self.url, self.port, self.token = m.group(0), int(m.group(1)), m.group(2)

    def text(self):
        return self.log.read_text()

    def stop(self):
        """^C, as a user in the shell would; the exit status."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        try:
            return self.proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise


@pytest.fixture(scope="module")
def lab_server(tmp_path_factory):
    """A lab server for the module; stopped with ^C unless a test ended it (BYE)."""
    server = LabServer(tmp_path_factory.mktemp("lab"))
    yield server
    status = server.stop()
    assert status == 0, f"the lab exited with {status}:\n{server.text()}"
    assert "blocks flushed; disk" in server.text()


@pytest.fixture(scope="session")
def browser():
    if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
        # make test runs `make lab-browser` first (mk/lab.mk): only where Debian's
        # chromium cannot be installed does this skip, and it says so.
        pytest.skip("browser tests need Debian's chromium and chromium-driver "
                    f"({CHROMIUM}, {CHROMEDRIVER}): `make lab-browser` could not install them")
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1600,900", "--hide-scrollbars"):
        options.add_argument(arg)
    driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=options)
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    yield driver
    driver.quit()


def wait_for(what, condition, timeout=30, poll=0.05):
    """Poll condition() until it is true; its last value, or an AssertionError."""
    deadline = time.monotonic() + timeout
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(poll)


