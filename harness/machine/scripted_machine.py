"""The FORTH on build/pdp11, driven line by line at deterministic instants.

Why not the keyboard: a line typed into the pty lands at whatever instruction
count the simulator has reached when the host gets round to writing it, and the
servo and the plant keep moving while the FORTH waits; two runs of one script
would then differ. Here the simulator stops itself at the kernel's prompt:
QUERY (reached once per line, after the previous line's " ok" or error report)
starts with AWAIT-LINE, whose read of the DL11's status register is the cue the
CUE device stops at (pdp11-devices/simh/prompt_cue.c: no per-instruction breakpoint
test, so the FORTH runs at full speed). While it is stopped the next line is deposited into
the kernel's console receive ring exactly as if the receive interrupt had just
stored it (type-ahead); then it runs on. Every stop and every character thus
falls on an instruction count that depends only on the script: the transcript
and the plant trace are the same on every run and every host.

    with ScriptedMachine(disk, trace="run.csv") as m:
        m.boot_output                  # the banner, up to the first prompt
        a = m.line("1 2 + .")          # Answer(output="1 2 + . 3  ok\\r", ...)
        m.wait(2.5)                    # 2.5 simulated seconds with no input
        m.simh("show plant")           # a SIMH command's output

A line that does not reach the next prompt within `line_limit` simulated seconds
(SIMH `STEP`) is stopped and reported; `interrupt()` then types ^C, which the
FORTH's receive interrupt takes at once. Addresses come from build/kernel.map.
"""
import contextlib
import os
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pexpect

from harness.machine import pty_child
from harness.machine.build import KERNEL, KERNEL_MAP, MACHINE_INI, PDP11, ROOT
from harness.machine.kernel_layout import KernelMapError, read_kernel_map
from harness.machine.pty_spawn import Spawn
from harness.machine.ring_image import ring_image, ring_pieces
from harness.machine.simh import examined

KERNEL_SYMBOLS = ("AWAIT-LINE", "RXHEAD", "RXTAIL", "RING", "RING-MASK", "TIB-SIZE")

PROMPT = "sim> "
END_WAIT = "deposit cpu wait 0"     # as the receive interrupt ends the WAIT in KEY
# WAIT (the kernel's KEY with an empty ring, e.g. during #wait) skips straight to
# the next event instead of counting one instruction time per host loop: the same
# simulated time and instruction counts, far less host work. SIMH's own switch (a
# hidden CPU register). Not for the console: idle time there is paced to the
# wall clock at the clock's ticks (pdp11-devices/bus/kw11l.c), which this would skip.
SKIP_WAITS = "deposit cpu wait_enable 1"
# SIMH reports every stop as "\n<reason>, PC: <octal> (<instruction>)\n" then prompts.
STOP = re.compile(r"\r\n([^\r\n]*), PC: ([0-7]+) \(([^\r\n]*)\)\r\nsim> ")
MAX_STEP = 2**31 - 1
EXAMINED = re.compile(r"([0-7]+):\s+([0-7]+)")
# pdp11-devices/simh/rl_one_writer.c's refusal, after which the simulator exits
DISK_HELD_LINE = re.compile(r"RL\d: [^\r\n]* is in use by [^\r\n]*")


class ScriptError(RuntimeError):
    """The machine could not be driven as asked (not a FORTH error); `output`
    is what SIMH printed when it refused a command."""

    def __init__(self, message, output=""):
        super().__init__(message)
        self.output = output


@dataclass
class Answer:
    output: str          # the console output: echo, what the line printed, " ok" or error
    error: str = ""      # the FORTH's error message ("" if none)
    stopped: str = ""    # why the simulator stopped if not at the next prompt
    running: bool = False  # stopped at the line limit: the line is still running

    @property
    def ok(self):
        return not self.error and not self.stopped


def feed_commands(sym, text, head):
    """SIMH deposits that put `text` and its CR into the FORTH's console receive
    ring at index `head` (the ring must be empty: RXTAIL = RXHEAD = head) and
    advance RXHEAD, exactly as the DL11 receive interrupt would have; and, as
    that interrupt would, end a WAIT the kernel's KEY sleeps in (after `#wait`
    the machine stops there; the CPU then goes on to test the ring again)."""
    pieces, after = ring_pieces(sym, text, head)
    return [f"deposit -b {address + i:o} {byte:o}"
            for address, piece in pieces for i, byte in enumerate(piece)] + \
        [f"deposit {sym['RXHEAD']:o} {after:o}", END_WAIT]


FORTH_ERROR = re.compile(r"\r\nError: ([^\r\n]*)")


class ScriptedMachine(contextlib.AbstractContextManager):
    def __init__(self, disk, trace=None, simulator=PDP11, kernel=KERNEL,
                 kernel_map=KERNEL_MAP, line_limit=60.0, wall_timeout=300, cwd=ROOT,
                 settings=(), cue_breakpoint=False, read_only=False):
        """`disk` and `trace` are attached as given, relative to `cwd`: SIMH
        prints them in SHOW, so a scripted run passes bare names; `read_only`
        attaches the disk so (ATTACH -R). `settings` are SIMH commands run
        before the trace is attached (SET PLANT ...).
        `cue_breakpoint`: stop at the cue by a SIMH breakpoint on its address
        instead (slower; the test that the CUE device stops at the same place)."""
        for what, path in (("simulator", simulator), ("kernel", kernel),
                           ("disk", Path(cwd) / disk)):
            if not Path(path).is_file():
                raise ScriptError(f"the {what} {path} does not exist (run make)")
        try:
            self.sym = read_kernel_map(kernel_map, KERNEL_SYMBOLS)
        except KernelMapError as e:
            raise ScriptError(str(e)) from e
        self.max_line = self.sym["TIB-SIZE"] - 1          # what ACCEPT takes
        self.cue = self.sym["AWAIT-LINE"] + 4    # after its TST @#177560: at QUERY
        self.line_limit = line_limit
        self._tmp = tempfile.TemporaryDirectory(prefix="scripted-machine-")
        # each line's LOAD image (ring_image.py), rewritten in place: LOAD reads up to
        # the image's end block, so what a longer line left after it is never read
        # (opening for writing or truncating took over a millisecond here, as long
        # as the rest of the line's round trip)
        self._feed = Path(self._tmp.name) / "line.lda"
        self._feed_fd = os.open(self._feed, os.O_RDWR | os.O_CREAT, 0o600)
        ini = Path(self._tmp.name) / "boot.ini"
        ini.write_text(f"do {MACHINE_INI}\n"
                       f"{SKIP_WAITS}\n"
                       f"attach {'-r ' if read_only else ''}rl0 {disk}\n"
                       + "".join(f"{c}\n" for c in settings)
                       + (f"attach plant {trace}\n" if trace else "")
                       + f"load {Path(kernel).resolve()}\n"
                       + (f"break {self.cue:o}\n" if cue_breakpoint
                          else f"deposit cue pc {self.cue:o}\n"))
        # echo off: SIMH's commands are not echoed, so its output is all there is
        self.child = Spawn(str(simulator), [str(ini)], cwd=str(cwd), echo=False,
                           encoding="latin-1", timeout=wall_timeout,
                           dimensions=(24, 200))
        self.child.delaybeforesend = None
        self.child.delayafterread = None       # pexpect's default sleeps 0.1 ms a read
        self._expect_prompt("the boot script")
        self.rate = self._clock_rate()
        self._head = None       # the ring's index after a line that reached QUERY
        self.trace = trace
        self.boot_output = self._run("go", "boot").output

    def left_with_bye(self, answer):
        """The line ran the FORTH's BYE: FLUSH, then the HALT at (BYE)."""
        bye = self.sym.get("(BYE)")
        return bye is not None and answer.stopped.startswith(f"HALT instruction, PC: {bye + 2:06o}")

    # ---- SIMH round trips -------------------------------------------------------------
    def _expect_prompt(self, what):
        i = self.child.expect_exact([PROMPT, pexpect.EOF, pexpect.TIMEOUT])
        held = DISK_HELD_LINE.search(self.child.before)
        if i == 1 and held:                     # another simulator writes the disk
            raise ScriptError(held.group(0))
        if i:
            raise ScriptError(f"the simulator {'exited' if i == 1 else 'did not answer'} "
                              f"during {what}: {self.child.before[-500:]!r}")
        text = self.child.before
        if re.search(r"(?m)^(%SIM-ERROR|.*(error|Error|not found|Non-existent|Invalid))", text):
            raise ScriptError(f"the simulator reported, during {what}: {text.strip()}", text)
        return text

    def simh(self, command):
        """Run one SIMH command at the prompt; its output (CR LF as printed)."""
        self._head = None       # the command may change the ring: read it again
        self.child.send(command + "\r")
        return self._expect_prompt(command)

    def _clock_rate(self):
        m = re.search(r"rate=(\d+)", self.simh("show clk"))
        if not m:
            raise ScriptError("SHOW CLK gave no rate: is this build/pdp11?")
        return int(m.group(1))

    def _run(self, command, what, extra_prompts=0):
        """Send `command` (which runs the machine) and wait for the stop."""
        self.child.send(command + "\r")
        i = self.child.expect([STOP, pexpect.EOF, pexpect.TIMEOUT])
        text = self.child.before
        if i:
            raise ScriptError(f"the simulator {'exited' if i == 1 else 'did not stop'} "
                              f"during {what}: {text[-500:]!r}")
        for _ in range(extra_prompts):        # one prompt per command sent before
            if not text.startswith(PROMPT):
                raise ScriptError(f"the simulator reported, during {what}: {text.strip()}")
            text = text[len(PROMPT):]
        reason, pc = self.child.match.group(1), int(self.child.match.group(2), 8)
        if reason == "Breakpoint" and pc == self.cue:
            stopped = ""
        elif reason == "Step expired":
            stopped = "step"
        else:
            stopped = f"{reason}, PC: {pc:06o} ({self.child.match.group(3)})"
        m = FORTH_ERROR.search(text)
        return Answer(text, m.group(1) if m else "", stopped)

    def _steps(self, seconds):
        return max(1, round(seconds * self.rate))

    def _run_for(self, seconds, what, before="", extra_prompts=0):
        """`before` (commands), then run for `seconds` of simulated time or to a
        stop, in STEPs of at most 31 bits (SIMH's limit: 161 s of SET CLK
        TIMED's units); the Answer, its output that of every STEP."""
        steps, outputs = self._steps(seconds), []
        while True:
            chunk = min(steps, MAX_STEP)
            answer = self._run(f"{before}step {chunk}", what, extra_prompts)
            outputs.append(answer.output)
            steps, before, extra_prompts = steps - chunk, "", 0
            if answer.stopped != "step" or steps == 0:
                answer.output = "".join(outputs)
                return answer

    # ---- what a script does ---------------------------------------------------------
    def line(self, text, limit=None):
        """Type one line (as if typed ahead) and run until the next prompt, or
        for `limit` simulated seconds (default line_limit) if it takes longer."""
        if len(text) > self.max_line:
            raise ScriptError(f"line longer than {self.max_line} characters")
        if any(not (32 <= ord(c) < 127 or c == "\t") for c in text):
            raise ScriptError("line holds a control or non-ASCII character")
        head = self._ring_head()
        image, after = ring_image(self.sym, text, head)
        os.pwrite(self._feed_fd, image, 0)
        limit = self.line_limit if limit is None else limit
        # the ring and RXHEAD as feed_commands' deposits leave them, and the end of WAIT
        answer = self._run_for(limit, text, before=f"load {self._feed}\r{END_WAIT}\r",
                               extra_prompts=2)
        if not answer.stopped:   # back at QUERY: ACCEPT took the line and its CR
            self._head = after
        return self._limited(answer, limit)

    def _ring_head(self):
        """Where the next line goes: known after a line that reached QUERY (no
        other input arrives in a scripted run), otherwise read and checked."""
        if self._head is not None:
            return self._head
        found = dict(EXAMINED.findall(self.simh(
            f"examine {self.sym['RXHEAD']:o}:{self.sym['RXTAIL']:o}")))
        head = int(found[f"{self.sym['RXHEAD']:o}"], 8)
        if head != int(found[f"{self.sym['RXTAIL']:o}"], 8):
            raise ScriptError("the console ring is not empty at the prompt")
        return head

    def resume(self, limit=None):
        """Let a line that is still running go on to the next prompt (or for
        `limit` simulated seconds more)."""
        limit = self.line_limit if limit is None else limit
        self._head = None
        return self._limited(self._run_for(limit, "resume"), limit)

    def interrupt(self, limit=None):
        """Type ^C, as a user stops a runaway line, and run to the next prompt (or
        for `limit` simulated seconds). The character arrives through the DL11 as
        a key would (RBUF = 3, DONE, and the receive interrupt when IE is set), not
        through the ring: the kernel's receive interrupt turns it into THROW -28."""
        ie = examined(self.simh("examine tti ie")).get("IE")
        for command in ("deposit tti buf 3", "deposit tti done 1") + (
                ("deposit tti int 1",) if ie else ()):
            self.simh(command)
        return self.resume(limit)

    @staticmethod
    def _limited(answer, limit):
        if answer.stopped == "step":
            answer.stopped = (f"no prompt within {limit:g} simulated seconds "
                              "(the line is still running)")
            answer.running = True
        return answer

    def run_to(self, address, limit):
        """Run until the instruction at `address` is next (a SIMH breakpoint, removed
        again), at most `limit` simulated seconds; the Answer (`stopped` names the
        breakpoint, or says the time ran out). The prompt's cue stays set."""
        self.simh(f"break {address:o}")
        try:
            answer = self._run_for(limit, f"run to {address:o}")
        finally:
            self.simh(f"nobreak {address:o}")
        return self._limited(answer, limit)

    def wait(self, seconds):
        """Let `seconds` of simulated time pass with no input; the output."""
        self._head = None
        answer = self._run_for(seconds, f"#wait {seconds}")
        if answer.stopped == "step":
            answer.stopped = ""
        elif not answer.stopped and not answer.error:
            answer.stopped = "the FORTH reached its prompt again while waiting"
        return answer

    def close(self):
        """Detach the trace (its rows end here) and quit: SIMH's QUIT writes the
        FORTH's UPDATEd blocks first (pdp11-devices/simh/leave_check.c), or, when it
        cannot, leaves without them (QUIT -F), and detaches the disk."""
        try:
            if self.trace and self.child.isalive():
                self.simh("detach plant")
            pty_child.quit_simh(self.child, timeout=10)
        except (ScriptError, pexpect.TIMEOUT, pexpect.EOF, OSError):
            pass            # a simulator already gone or stuck: killed below
        pty_child.close(self.child)
        if self._feed_fd is not None:        # close() may come twice (Robot, __exit__)
            os.close(self._feed_fd)
            self._feed_fd = None
        self._tmp.cleanup()

    def __exit__(self, *exc):
        self.close()
