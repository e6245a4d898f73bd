"""Two labs in one browser (issue 23): each tab keeps its own token in its
sessionStorage (per origin, the port included), no cookie carries one, and each
tab keeps working after a reload."""
import signal
import subprocess
import sys

import pytest

from harness.lab.launch import LabProcess
from harness.machine.build import ROOT
from tests.process_ends import ended_within
from labpage import connected, full_session, type_line

pytestmark = full_session


@pytest.fixture(scope="module")
def second_lab(tmp_path_factory):
    server = LabProcess(tmp_path_factory.mktemp("lab2"))
    yield server
    assert server.stop() == 0


def test_two_labs_in_one_browser_each_keep_working_after_a_reload(lab_server, second_lab,
                                                                 browser):
    first = browser.current_window_handle
    browser.get(lab_server.url)
    connected(browser)
    browser.switch_to.new_window("tab")
    second = browser.current_window_handle
    browser.get(second_lab.url)
    connected(browser)
    for handle, line, answer in ((first, "2 3 + .", "5  ok"), (second, "3 4 + .", "7  ok")):
        browser.switch_to.window(handle)
        assert answer in type_line(browser, line, answer)
        assert "token=" not in browser.current_url          # off the address bar
        assert browser.get_cookies() == []                  # nothing that authenticates
        browser.refresh()
        connected(browser)
        assert "token=" not in browser.current_url
        assert "6  ok" in type_line(browser, "1 5 + .", "6  ok")
    browser.close()
    browser.switch_to.window(first)


# A starter that dies without quitting its browser: chromedriver's pid and Chromium's
# (the driver's children), then killed.
KILLED_BROWSER_STARTER = """
import os
from pathlib import Path
from harness.lab.launch import headless_browser
driver = headless_browser(800, 600)
driver.get("about:blank")
pid = driver.service.process.pid
print(pid, *(t.read_text() for t in Path(f"/proc/{pid}/task").glob("*/children")), flush=True)
os.kill(os.getpid(), 9)
"""


@full_session
def test_a_browser_ends_when_the_process_that_started_it_is_killed():
    """chromedriver ends with its starter and Chromium with chromedriver (launch.py,
    parent_death.py): a killed test run leaves no browser behind."""
    starter = subprocess.run([sys.executable, "-c", KILLED_BROWSER_STARTER], cwd=ROOT,
                             capture_output=True, text=True, timeout=60)
    assert starter.returncode == -signal.SIGKILL, starter.stderr
    driver, *browser = map(int, starter.stdout.split())
    assert browser, "chromedriver had started no Chromium"
    assert ended_within([driver, *browser], 15), "the browser outlived its killed starter"
