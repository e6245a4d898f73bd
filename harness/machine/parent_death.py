"""Children that end when the process that started them ends, however it ends.

A lab, a chromedriver or a Chromium started by a test or a benchmark outlived a
starter that was killed (SIGKILL, a crash, a CI timeout): nothing ran its stop().
The lab then kept its simulator running at ten times the 11/23's pace, holding a
disk, and Chromium kept its renderers. Linux's parent-death signal
(prctl PR_SET_PDEATHSIG) asks the kernel to send a signal to the child when its
parent goes; it survives exec, so it is set once, before the program starts.

ended_with_parent(argv, signal): the command line, run under util-linux's
    `setpriv --pdeathsig` (Essential in Debian): no Python runs in the child, so
    the start stays as cheap as subprocess's vfork.
ended_with_parent_preexec(signal): the same as a preexec_fn, for a caller that
    cannot change the command line (Selenium's Service builds its own).

The signal goes when the *thread* that started the child ends: start these from a
thread that lives as long as the child should (the main thread, as every caller
does)."""
import ctypes
import os
import signal as signals

SETPRIV = "setpriv"
PR_SET_PDEATHSIG = 1


def ended_with_parent(argv, signal=signals.SIGTERM):
    """argv, started so that it gets `signal` when its parent ends."""
    return [SETPRIV, "--pdeathsig", signals.Signals(signal).name.removeprefix("SIG"), *argv]


def ended_with_parent_preexec(signal=signals.SIGTERM):
    """A preexec_fn that sets the parent-death signal (and ends the child at once if
    the parent is already gone: the signal is only sent for a death after it is set)."""
    parent = os.getpid()
    prctl = ctypes.CDLL(None, use_errno=True).prctl   # looked up here: the child of a
                                                      # threaded process only calls it

    def preexec():
        if prctl(PR_SET_PDEATHSIG, int(signal), 0, 0, 0) != 0:
            raise OSError(ctypes.get_errno(), "prctl(PR_SET_PDEATHSIG)")
        if os.getppid() != parent:
            os.kill(os.getpid(), signal)
    return preexec
