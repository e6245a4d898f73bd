"""The FORTH on build/pdp11 through a pty, a line at a time as a user types it
(each line lands when the host writes it; scripted_machine.py is the lock-step,
deterministic driver).

    with Machine(disk=path) as m:      # boots to the FORTH prompt
        m.send("1 2 + .")              # -> "3 "   (raises ForthError on an error)
        m.reply("1 @")                 # -> Reply(ok=False, output=..., error=...)

Flow control: a line is sent only after the previous one was answered (" ok",
" compiled" while a definition is open, or "Error: ..."), and the answer is
awaited with pexpect (no sleeps). A simulator halt (the sim> prompt) or EOF raises MachineHalted; a missing answer raises
TimeoutError. The simulator is harness.machine.build's PDP11 (PDP11_SIM honoured).
"""
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pexpect

from harness.blocks.disk import RL02_BYTES
from harness.machine import pty_child
from harness.machine.build import KERNEL, ROOT  # noqa: F401
from harness.machine.build import PDP11 as SIMULATOR
from harness.machine.pty_spawn import Spawn
from harness.machine.simh import boot_script

OK = re.compile(r" (?:ok|compiled)\r\n")   # compiled: a definition or structure is open
ERROR = re.compile(r"\r\nError: ([^\r\n]*)\r\n")
SIM_PROMPT = re.compile(r"sim> ")
# While the FORTH waits for a line (KEY in WAIT) simulated time passes at 100 times
# the 11/23's pace (pdp11-devices/bus/kw11l.c, SET CLK IDLESPEED): unpaced, it raced
# at about 700 times, a host core busy between two lines for nothing (measured: half
# the CPU of the FORTH tests that drive this machine); busy stretches run at full speed.
IDLE_PACE = "set cpu idle\nset clk idlespeed=100\n"


class MachineHalted(RuntimeError):
    """The simulator stopped (HALT, trap to the simulator prompt, EOF)."""


class ForthError(RuntimeError):
    """The FORTH answered a line with an error report."""

    def __init__(self, line, message, output):
        super().__init__(f"{line!r}: {message}")
        self.line, self.message, self.output = line, message, output


@dataclass
class Reply:
    ok: bool
    output: str        # what the line printed, without its echo and " ok"
    error: str = ""    # the error message ("" when ok)


def blank_disk(path):
    """A fresh RL02-size image of zeros (block n = bytes 1024n..1024n+1023)."""
    path = Path(path)
    with open(path, "wb") as f:
        f.truncate(RL02_BYTES)
    return path


class Machine:
    def __init__(self, disk=None, simulator=SIMULATOR, kernel=KERNEL, timeout=30,
                 extra_commands=""):
        self.timeout = timeout
        self._tmp = tempfile.TemporaryDirectory(prefix="forth-machine-")
        tmp = Path(self._tmp.name)
        self.disk = Path(disk) if disk else blank_disk(tmp / "rl0.dsk")
        ini = tmp / "boot.ini"
        ini.write_text(boot_script(self.disk, kernel, setup=IDLE_PACE + extra_commands))
        self.child = Spawn(str(simulator), [str(ini)], cwd=str(ROOT),
                           encoding="latin-1", timeout=timeout,
                           dimensions=(24, 200))
        self.child.delaybeforesend = None  # pexpect would wait 50 ms per send
        self.child.delayafterread = None   # ... and 0.1 ms after each read: half a line's
                                           # wall time where a test types a thousand
        self.at_sim_prompt = False
        try:
            self.banner = self._expect_ok_or_halt("boot")
        except Exception:
            self.close()
            raise

    # ---- low level -------------------------------------------------------------
    def _expect_ok_or_halt(self, what):
        i = self.child.expect([OK, SIM_PROMPT, pexpect.EOF, pexpect.TIMEOUT])
        if i == 0:
            return self.child.before
        self._stopped(what, timed_out=(i == 3))

    def _stopped(self, what, timed_out):
        self.at_sim_prompt = not timed_out
        text = self.child.before if isinstance(self.child.before, str) else ""
        if timed_out:
            raise TimeoutError(f"no answer to {what!r} within {self.timeout} s: {text[-500:]!r}")
        raise MachineHalted(f"simulator stopped during {what!r}: {text[-500:]!r}")

    # ---- lines -------------------------------------------------------------------
    def reply(self, line, timeout=None):
        """Send one line (CR-terminated); wait for " ok" or an error report."""
        if "\r" in line or "\n" in line:
            raise ValueError("one line at a time")
        self.child.send(line + "\r")
        return self.answer(line, timeout)

    def answer(self, line, timeout=None):
        """The FORTH's answer to `line`, already typed (reply's; a test that types
        lines ahead of their answers reads them one by one)."""
        i = self.child.expect([OK, ERROR, SIM_PROMPT, pexpect.EOF, pexpect.TIMEOUT],
                              timeout=timeout or self.timeout)
        text = self.child.before
        echo = line.replace("\t", " ")  # the FORTH reads a tab as a blank
        if text.startswith(echo):
            text = text[len(echo):]
        if text.startswith(" "):
            text = text[1:]
        if i == 0:
            return Reply(True, text)
        if i == 1:
            return Reply(False, text, self.child.match.group(1))
        self._stopped(line, timed_out=(i == 4))

    def send(self, line, timeout=None):
        """Send one line; its output, or ForthError if it failed."""
        r = self.reply(line, timeout)
        if not r.ok:
            raise ForthError(line, r.error, r.output)
        return r.output

    def send_lines(self, text, timeout=None):
        """Send several lines; their outputs concatenated."""
        return "".join(self.send(line, timeout) for line in text.splitlines())

    # ---- SIMH's sim> prompt -------------------------------------------------------
    def to_sim(self, timeout=None):
        """^E: the machine stops at sim> (waiting there, the simulator uses no CPU)."""
        self.child.sendcontrol("e")
        self.child.expect(SIM_PROMPT, timeout=timeout or self.timeout)
        self.at_sim_prompt = True

    def simh(self, command):
        """One SIMH command at sim>; what it printed."""
        self.child.sendline(command)
        self.child.expect(SIM_PROMPT)
        return self.child.before

    def cont(self):
        """CONT: the machine runs again, the FORTH answering (pty_child.probe_prompt);
        then a line whose answer is waited for, so that no late answer to the probe's
        empty lines is taken for the next line's."""
        self.child.sendline("cont")
        self.at_sim_prompt = False
        probed = pty_child.probe_prompt(self.child)
        if probed != 0:
            self._stopped("CONT", timed_out=(probed == 2))
        self.child.send(".( resumed)\r")
        self.child.expect(r"\) resumed ok\r\n", timeout=self.timeout)   # its echo, its text

    # ---- shutdown -----------------------------------------------------------------
    def close(self):
        if self.child.isalive():
            try:
                if not self.at_sim_prompt:
                    self.to_sim(timeout=5)
                pty_child.quit_simh(self.child, timeout=5)   # FLUSHes, or -F
            except (pexpect.TIMEOUT, pexpect.EOF, OSError):
                pass
            pty_child.close(self.child)
        self._tmp.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
