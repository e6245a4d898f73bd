"""Children started with harness/machine/parent_death.py end when their starter is
killed (SIGKILL: no stop() runs), and live as long as it does."""
import os
import subprocess
import sys
import time

from harness.machine.build import ROOT
from tests.process_ends import ended_within, running

# A starter: two sleeps, one under setpriv's --pdeathsig and one with the preexec_fn;
# their pids on a line, then it waits to be killed.
STARTER = """
import subprocess, sys, time
from harness.machine.parent_death import ended_with_parent, ended_with_parent_preexec
a = subprocess.Popen(ended_with_parent(["sleep", "60"]))
b = subprocess.Popen(["sleep", "60"], preexec_fn=ended_with_parent_preexec())
print(a.pid, b.pid, flush=True)
time.sleep(60)
"""


def test_children_live_with_their_starter_and_end_when_it_is_killed():
    starter = subprocess.Popen([sys.executable, "-c", STARTER], cwd=ROOT, stdout=subprocess.PIPE,
                               text=True)
    try:
        children = list(map(int, starter.stdout.readline().split()))
        assert len(children) == 2
        time.sleep(0.2)
        assert all(map(running, children)), "a child ended while its starter lived"
        starter.kill()
        starter.wait()
        assert ended_within(children, 5), "a child outlived its killed starter"
    finally:
        starter.kill()
        for pid in children:
            if running(pid):
                os.kill(pid, 9)
