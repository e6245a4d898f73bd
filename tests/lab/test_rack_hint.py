"""The hint for a move that waits on a switched-off amplifier rack."""
from harness.lab.rack_hint import HINT, HINT_AFTER_S, RackHint

BUSY, IDLE = {"Command.Status": [1, 0, 0, 0]}, {"Command.Status": [0, 0, 0, 0]}


def test_once_per_wait_and_only_with_the_rack_off():
    hint = RackHint()
    assert hint.update("off", 10.0, BUSY) is None                  # the move just began
    assert hint.update("off", 10.0 + HINT_AFTER_S, BUSY) == HINT
    assert hint.update("off", 30.0, BUSY) is None                  # said once
    assert hint.update("off", 31.0, IDLE) is None                  # ^C, the move abandoned...
    assert hint.update("off", 32.0, BUSY) is None
    assert hint.update("off", 32.0 + HINT_AFTER_S, BUSY) == HINT  # ...a new wait: said again
    hint = RackHint()
    assert all(hint.update("on", t, BUSY) is None for t in (0.0, 5.0, 50.0))
    assert all(hint.update("off", t, {}) is None for t in (0.0, 5.0, 50.0))   # before 1000 LOAD
