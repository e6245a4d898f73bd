"""Start a lab as a user would, in its own process, and a headless Chromium to look
at it: shared by the lab's tests and its benchmark."""
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

from harness.machine.build import ROOT, fresh_disk
from harness.machine.parent_death import ended_with_parent, ended_with_parent_preexec

CHROMIUM, CHROMEDRIVER = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")
# Chromium as the driver starts it: ended with the driver (parent_death.py)
CHROMIUM_ENDED_WITH_DRIVER = Path(__file__).with_name("chromium-ended-with-driver")
URL = re.compile(r"http://127\.0\.0\.1:(\d+)/\?token=(\S+)")


class LabProcess:
    """`python -m harness lab` on a copy of the pristine disk, on a free port; ten times
    the 11/23's pace unless asked otherwise: at full speed a lab whose FORTH waits at
    its prompt races simulated time, a host core busy for nothing (measured: half of
    the lab tests' simulator CPU), while x10 still runs a 1000 LOAD in half a second.
    A starter that dies without stop() takes the lab with it: the lab gets the ^C
    (SIGINT) it would have sent, and ends its simulator as a user's ^C does."""

    def __init__(self, tmp, speed="x10", timed=False):
        """Starts the lab; its URL is waited for when first asked (url, port, token),
        so a caller may start a browser meanwhile."""
        self.disk = disk = fresh_disk(tmp)
        self.log = Path(tmp) / "lab.log"
        with open(self.log, "w") as log:
            self.proc = subprocess.Popen(
                ended_with_parent([sys.executable, "-m", "harness", "lab", "--port", "0",
                                   "--speed", speed, "--disk", str(disk)]
                                  + (["--timed"] if timed else []), signal.SIGINT),
                cwd=ROOT, stdout=log, stderr=subprocess.STDOUT)
        self._started = time.monotonic()
        self._served = None

    def _announced(self):
        """The URL the lab printed: (url, port, token), waited for once."""
        deadline = self._started + 30
        while self._served is None:
            m = URL.search(self.text())
            if m:
                self._served = m.group(0), int(m.group(1)), m.group(2)
            elif self.proc.poll() is not None or time.monotonic() > deadline:
                self.proc.kill()
                raise RuntimeError(f"the lab server did not start:\n{self.text()}")
            else:
                time.sleep(0.02)
        return self._served

    url = property(lambda self: self._announced()[0])
    port = property(lambda self: self._announced()[1])
    token = property(lambda self: self._announced()[2])

    def text(self):
        return self.log.read_text()

    def simulator_pid(self):
        self._announced()                  # the simulator is started before the URL is printed
        children = Path(f"/proc/{self.proc.pid}/task/{self.proc.pid}/children").read_text()
        return int(children.split()[0])

    def stop(self):
        """^C, as a user in the shell would; the exit status."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        try:
            return self.proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise


def have_browser():
    return CHROMIUM.exists() and CHROMEDRIVER.exists()


# The new headless mode is the whole browser: at its start it loads the omnibox's
# popups (chrome://omnibox-popup.top-chrome, a web page in a renderer of its own) for
# an address bar nobody types in, some 0.7 CPU-s of each start. Only the browser's
# own menus go: the pages are drawn as before.
NO_BROWSER_UI = "--disable-features=WebUIOmniboxPopup,WebUIOmniboxAimPopup"


def headless_browser(width=1920, height=1080):
    """Debian's Chromium through its chromium-driver (Selenium downloads nothing), the
    page width x height, as a projector shows it full screen. --window-size is the
    window's: the new headless mode draws a browser's frame inside it (tab strip,
    toolbar: 143 pixels of 1080 high), so the window is grown by the frame."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM_ENDED_WITH_DRIVER)
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                f"--window-size={width},{height}", "--hide-scrollbars", NO_BROWSER_UI):
        options.add_argument(arg)
    # the driver ends with this process, and Chromium with the driver (parent_death.py)
    service = Service(str(CHROMEDRIVER), env={**os.environ, "LAB_CHROMIUM": str(CHROMIUM)},
                      popen_kw={"preexec_fn": ended_with_parent_preexec()})
    driver = webdriver.Chrome(service=service, options=options)
    frame = driver.execute_script("return [outerWidth - innerWidth, outerHeight - innerHeight]")
    if any(frame):
        driver.set_window_size(width + frame[0], height + frame[1])
    return driver
