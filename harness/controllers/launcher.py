"""`make run CONTROLLERS=4`: the five machines, the 11/23's console in front
(harness/machine/console_session.py, as `make run` has it) and the four LSI-11/03s
behind it, each on its pty served by bridge.py.

    launch(fast=..., trace=...) -> exit status (the front console's)

The session lives in local/controllers/ (mode 0700): the sockets, the token,
each 11/03's console log (x.log ...; the 11/23's is main.log) and disk (x.dsk: a fresh copy of the pristine
disk at every launch, one writer each). The 11/03s boot their kernel
(build/kernel-1103.lda) and, when their disk holds block 1080, are typed their
boot lines (boot_lines.py) at their prompts. The 11/23 is the user's, on the
user's working disk; `1090 LOAD` gives it the link words. When the user leaves
the 11/23 (BYE), the coordinator ends the session: each 11/03 stops at sim>, is
told QUIT and exits; an 11/03 that does not (held at its sim> by a client) is
ended after END_WAIT seconds. A killed 11/03 is said at the 11/23's console by
the 11/23 itself (LOCKSTEP device); the launcher goes on without it.
"""
import secrets
import shutil
import sys
import threading
import time
from pathlib import Path

from harness.controllers.boot_lines import MAIN_BOOT_LINES, axis_boot_lines
from harness.controllers.bridge import ConsoleBridge
from harness.controllers.coordinator import CONTROLLERS, Coordinator, member_settings
from harness.controllers.members import SESSION_OVER
from harness.controllers.scripted import axis_blocks_present
from harness.machine import pty_child, simh
from harness.machine.build import (CONTROLLERS_DIR, KERNEL, KERNEL_1103, PDP11, PRISTINE_DISK,
                                    fresh_disk)
from harness.machine.console_session import session
from harness.machine.pty_spawn import Spawn

STATUS = "status.json"       # the coordinator's status, for the lab's page of the five
END_WAIT = 10                # wall seconds the 11/03s get to stop and QUIT at the end
PROMPT = b" ok\r\n"


def say(line):
    print(f"[controllers] {line}")
    sys.stdout.flush()


def _boot_lines(bridge, name, lines):
    """Type each line at the 11/03's prompt, the next when the previous is answered."""
    if not lines:
        return
    first, rest = lines[0], lines[1:]
    bridge.when_printed(name, PROMPT, lambda: (bridge.type(name, first),
                                                _boot_lines(bridge, name, rest)))


class Launch:
    def __init__(self, directory=CONTROLLERS_DIR, axis_kernel=KERNEL_1103, disk=PRISTINE_DISK,
                 trace=None, boot_lines=None):
        self.directory = directory
        if directory.exists():
            shutil.rmtree(directory)            # the last session's sockets, logs, disks
        directory.mkdir(parents=True, mode=0o700)
        self.token = secrets.token_hex(16)
        (directory / "token").write_text(self.token)
        (directory / "token").chmod(0o600)
        self.coordinator = Coordinator(directory, trace=trace, status=directory / STATUS)
        self.bridge = ConsoleBridge(directory, self.token)
        self.children = {}
        if boot_lines is None:
            boot_lines = axis_blocks_present(disk)
        for i, name in enumerate(CONTROLLERS):
            copy = fresh_disk(directory, f"{name}.dsk", source=disk)
            ini = directory / f"{name}.ini"
            ini.write_text(simh.boot_script(copy, axis_kernel, setup="".join(
                f"{c}\n" for c in member_settings(name, self.coordinator.socket))))
            child = Spawn(str(PDP11), [str(ini)], cwd=str(directory), timeout=None)
            self.children[name] = child
            self.bridge.add(name, child)
            _boot_lines(self.bridge, name, axis_boot_lines(i) if boot_lines else [])
        self._running = True
        self._thread = threading.Thread(target=self._serve, name="consoles", daemon=True)
        self._thread.start()

    def _serve(self):
        while self._running:
            self.bridge.poll()

    def front(self, disk, fast=False, busy_wait=None):
        """The 11/23's console (the user's terminal) until the user leaves; its status."""
        for name, child in self.children.items():
            say(f"11/03 {name}: pid {child.pid}; its console: python -m harness "
                f"controllers console {name} (^] leaves it, ^E gives its sim>)")
        say(f"this terminal is the 11/23's console; {' then '.join(MAIN_BOOT_LINES)} gives it "
            "the words that drive the axes through the 11/03s")
        say("the plant is the coordinator's, its rack switched on: SET PLANT and SHOW PLANT "
            "at any machine's sim> act on it (^E, SET PLANT POWER=OFF, CONT: the axes stop "
            "being driven at the next 1 ms boundary)")
        extra = {"busy_wait": busy_wait} if busy_wait else {}
        return session(PDP11, disk, fast=fast, kernel=KERNEL, rack_hint=False,
                       log=self.directory / "main.log",
                       setup="".join(f"{c}\n" for c in member_settings(
                           "main", self.coordinator.socket)), **extra)

    def close(self):
        """End the 11/03s (QUIT once the session is over), the bridge, the coordinator."""
        deadline = time.monotonic() + END_WAIT
        for name in self.children:
            console = self.bridge.consoles[name]
            if self.bridge.wait_for(lambda c=console: not c.alive or any(
                    s.encode() in c.shown for s in SESSION_OVER), deadline - time.monotonic()) \
                    and console.alive:
                self.bridge.type(name, "quit")
        for name in self.children:
            console = self.bridge.consoles[name]
            if not self.bridge.wait_for(lambda c=console: not c.alive, deadline - time.monotonic()):
                say(f"11/03 {name} did not stop within {END_WAIT} s: ended")
        self._running = False
        self.bridge.wake()
        self._thread.join()
        for child in self.children.values():
            pty_child.close(child)
        self.bridge.close()
        self.coordinator.stop()
        self.coordinator.__exit__()


def launch(disk, fast=False, trace=None, busy_wait=None, boot_lines=None,
           directory=CONTROLLERS_DIR, page=None):
    """The whole `make run CONTROLLERS=4`: exit status 0 when the 11/23 left cleanly.
    page(directory) -> (url, stop): serves a page of the session (the lab's page of
    the five machines, given by the command: this package may not import the lab)."""
    say("booting five machines in lock-step (issue 21, docs/controllers.md): "
        "the 11/23 and the LSI-11/03s of x, y, z, t")
    five = Launch(directory=Path(directory), trace=trace, boot_lines=boot_lines)
    stop_page = None
    try:
        if page:
            url, stop_page = page(Path(directory))
            say(f"the five machines' page: {url} (open it in a browser on this machine)")
        return five.front(disk, fast=fast, busy_wait=busy_wait)
    finally:
        if stop_page:
            stop_page()
        five.close()
