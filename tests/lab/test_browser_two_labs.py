"""Two labs in one browser (issue 23): each tab keeps its own token in its
sessionStorage (per origin, the port included), no cookie carries one, and each
tab keeps working after a reload."""
import pytest

from harness.lab.launch import LabProcess
from labpage import connected, full_session, js, type_line, wait_for

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
