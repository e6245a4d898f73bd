"""pexpect.spawn, started without forking this Python process.

pexpect (ptyprocess) starts a child by forking the calling process and running
Python in the copy until exec: the copy's page tables, the pages it writes before
exec and its closing of every descriptor cost 9 ms of CPU a start in a test
worker that has matplotlib and aiohttp loaded (5 ms for pty.fork alone), 20 ms of
wall time. The suite starts some 400 simulators and harness commands that way.

Spawn does the same through subprocess, which starts the child with vfork and
exec and runs no Python in it (1.8 ms CPU, 8 ms wall): the pty is opened here,
its size and echo set on its terminal side, and the child made a session leader
with the pty as its controlling terminal by util-linux's `setsid --ctty`, which
then execs the program under the same pid. So the child sees what pty.fork gave
it: a new session, the pty as stdin/stdout/stderr and controlling terminal (^E
and ^C reach SIMH as signals through the line discipline), the size asked for,
no other descriptors, and SIGPIPE as this process has it (ignored: Python's
setting, which ptyprocess's children inherit too).

`tty_setup`: a function of the terminal's descriptor that sets its modes before
the child starts (in place of a preexec_fn, which would need the fork again).
A preexec_fn still works, through pexpect's own fork."""
import os
import subprocess
import termios

import pexpect
import ptyprocess

SETSID = "setsid"       # util-linux (Essential in Debian): --ctty takes stdin as the terminal


class _PtyProcess(ptyprocess.PtyProcess):
    @classmethod
    def spawn(cls, argv, cwd=None, env=None, echo=True, preexec_fn=None,
              dimensions=(24, 80), pass_fds=(), tty_setup=None):
        if preexec_fn is not None:
            return super().spawn(argv, cwd=cwd, env=env, echo=echo, preexec_fn=preexec_fn,
                                 dimensions=dimensions, pass_fds=pass_fds)
        master, terminal = os.openpty()
        try:
            termios.tcsetwinsize(terminal, dimensions)
            if not echo:
                mode = termios.tcgetattr(terminal)
                mode[3] &= ~termios.ECHO
                termios.tcsetattr(terminal, termios.TCSANOW, mode)
            if tty_setup is not None:
                tty_setup(terminal)
            launcher = subprocess.Popen([SETSID, "--ctty", *argv], stdin=terminal,
                                        stdout=terminal, stderr=terminal, cwd=cwd, env=env,
                                        pass_fds=pass_fds, restore_signals=False)
        except BaseException:
            os.close(master)
            raise
        finally:
            os.close(terminal)
        child = cls(launcher.pid, master)
        # ptyprocess reaps the child (isalive, wait, close); this object only
        # keeps subprocess from reporting it as a child never waited for
        child.launcher = launcher
        child.argv, child.env, child.launch_dir = argv, env, cwd
        return child


class Spawn(pexpect.spawn):
    """pexpect.spawn(command, args, ..., tty_setup=None), started as above."""

    def __init__(self, *args, tty_setup=None, **options):
        self._tty_setup = tty_setup
        super().__init__(*args, **options)

    def _spawnpty(self, args, **kwargs):
        return _PtyProcess.spawn(args, tty_setup=self._tty_setup, **kwargs)
