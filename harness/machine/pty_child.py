"""Closing a pexpect child without pexpect's fixed pause.

pexpect (ptyprocess) sleeps delayafterclose (0.1 s) on every close, to give a
child it is about to kill time to exit. A simulator that has already quit (EOF
read) needs no such wait: reap it and close at once. A scripted scenario spends
about half its wall time in that pause otherwise."""


def close(child):
    """Close `child`, killing it if it still runs; no pause if it has exited."""
    if not child.isalive():
        child.delayafterclose = child.ptyproc.delayafterclose = 0
    child.close(force=True)
