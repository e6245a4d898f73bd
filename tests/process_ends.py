"""Whether processes a test started (and cannot wait for: not its children) have ended."""
import time

from harness.machine.key_feed import process_state


def running(pid):
    """True while pid exists and is not a zombie."""
    return process_state(pid) not in ("Z", None)


def ended_within(pids, seconds):
    deadline = time.monotonic() + seconds
    while any(map(running, pids)) and time.monotonic() < deadline:
        time.sleep(0.02)
    return not any(map(running, pids))
