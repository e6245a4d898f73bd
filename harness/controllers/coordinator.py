"""The lock-step coordinator (build/lockstep-coordinator, pdp11-devices/lockstep/coordinator.c)
as a child process, and what each member's simulator is told to join it.

    with Coordinator(tmp, trace="trace.csv") as c:     # tmp: a private directory
        settings = member_settings("x", c.socket)       # SIMH lines for a member
        ...
        c.wait()                                        # after the 11/23 has left

The socket lies in a directory of mode 0700 made here (no port, so no token:
only this user's processes can reach it). MEMBERS names the five in the
coordinator's order: the 11/03s of x, y, z, t, then the 11/23 ("main").
"""
import os
import subprocess
import tempfile
import time
from pathlib import Path

from harness.machine.build import COORDINATOR, CPU_1103
from harness.machine.plant_rows import AXES

CONTROLLERS = tuple(AXES.lower())       # the 11/03s, named by their axes
MAIN = "main"
MEMBERS = CONTROLLERS + (MAIN,)


class CoordinatorError(RuntimeError):
    """The coordinator could not be started or failed."""


def member_settings(member, socket):
    """SIMH commands, after machine.ini, making a simulator the member `member` (x, y,
    z, t: an 11/03, build.CPU_1103; main: the 11/23) and joining the coordinator at
    `socket` (before the machine runs)."""
    if member not in MEMBERS:
        raise CoordinatorError(f"no member {member!r}: the members are {', '.join(MEMBERS)}")
    return ((CPU_1103 if member in CONTROLLERS else ())
            + (f"set lockstep role={member.upper()}", f"attach lockstep {socket}"))


class Coordinator:
    def __init__(self, directory=None, trace=None, members=MEMBERS, sample=60, seed=1983,
                 join_timeout=120, quanta=1000, status=None):
        """`trace`: the plant trace's path (None: none); `members`: who takes part;
        `directory`: where the trace's relative path is (cwd of the process);
        `quanta`: quanta per simulated second (1000: 1 ms, the plant's step; more
        only to measure what shorter ones cost); `status`: the status file's path
        (the lab's page of the five machines reads it), None for none."""
        if not COORDINATOR.exists():
            raise CoordinatorError(f"{COORDINATOR} does not exist: run make")
        self._private = tempfile.TemporaryDirectory(prefix="lockstep-")
        os.chmod(self._private.name, 0o700)
        self.socket = Path(self._private.name) / "sock"
        args = [str(COORDINATOR), str(self.socket), "--members", ",".join(members),
                "--sample", str(sample), "--seed", str(seed),
                "--join-timeout", str(join_timeout), "--quanta", str(quanta)]
        if trace:
            args += ["--trace", str(trace)]
        if status:
            args += ["--status", str(status)]
        self.proc = subprocess.Popen(args, cwd=directory, stderr=subprocess.PIPE, text=True)
        self._wait_for_socket()

    def _wait_for_socket(self):
        for _ in range(500):
            if self.socket.exists():
                return
            if self.proc.poll() is not None:
                raise CoordinatorError(f"the coordinator exited: {self.proc.stderr.read().strip()}")
            time.sleep(0.01)                 # start-up only: a guard, not simulated time
        raise CoordinatorError("the coordinator did not make its socket within 5 s")

    def wait(self, timeout=60):
        """Its exit status once the session is over (the 11/23 left); what it said."""
        try:
            _, err = self.proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired as e:
            raise CoordinatorError(f"the coordinator did not end within {timeout} s") from e
        return self.proc.returncode, err

    def stop(self):
        """End it now (the members still joined stop at their next boundary)."""
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()
        if self.proc.stderr:
            self.proc.stderr.close()
        self._private.cleanup()
