"""Lab tests: a lab server per module (python -m harness lab, at ten times the 11/23's
pace, on a copy of the pristine disk, on a free port) and one headless Chromium for the
session."""
import pytest

from harness.lab.launch import CHROMEDRIVER, CHROMIUM, LabProcess, have_browser, \
    headless_browser
from labpage import ARTIFACTS


@pytest.fixture(scope="module")
def lab_server(request, tmp_path_factory):
    """A lab server for the module, at the module's LAB_SPEED (default LabProcess's, x10),
    on the 11/23's clock if its LAB_TIMED says so; stopped with ^C unless a test ended
    it (BYE)."""
    speed = getattr(request.module, "LAB_SPEED", None)
    server = LabProcess(tmp_path_factory.mktemp("lab"), **({"speed": speed} if speed else {}),
                        timed=getattr(request.module, "LAB_TIMED", False))
    yield server
    status = server.stop()
    assert status == 0, f"the lab exited with {status}:\n{server.text()}"
    assert "FLUSH answered ok" in server.text()


@pytest.fixture(scope="session")
def browser():
    if not have_browser():
        # make test runs `make lab-browser` first (mk/lab.mk): only where Debian's
        # chromium cannot be installed does this skip, and it says so.
        pytest.skip("browser tests need Debian's chromium and chromium-driver "
                    f"({CHROMIUM}, {CHROMEDRIVER}): `make lab-browser` could not install them")
    # The smaller projector's size: Chromium rasterises and composites in software, its
    # work growing with the pixels; the tests of layout look at both sizes (projector()).
    driver = headless_browser(1280, 720)
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    yield driver
    driver.quit()
