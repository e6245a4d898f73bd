"""The checks of docs/exercises.md, run from the lab page's lessons (the page's
`check` message): each is the exercise's own commands, run on the host in a
scratch directory as the reader would type them, never on the lab's running
machine; exercise 5 runs on a copy of the lab's disk (what FLUSH wrote there).

The page names an exercise by number only: the commands are these, fixed.
"""
import asyncio
import shutil
import sys
import tempfile
from pathlib import Path

from harness.machine.build import ROOT

TIMEOUT_S = 300                  # a check that takes longer is stopped and says so
SHOWN_LINES = 60                 # the tail of what a check printed, for the page

HARNESS = (sys.executable, "-m", "harness")
DISK_COPY = "copy-of-the-lab-disk.dsk"
D2_SCRIPT = "1000 LOAD\nSet.Up.Robot\n4000 0 400 0 Abs.Move Move.Complete?\n"
D2_MEASURE = ("from harness.analysis import trace, moves\n"
              "m = moves.find_moves(trace.read('{tmp}/d2.trace.csv').axis('X'))[0]\n"
              "print(f'D2 - D0 = {{m.d2 - m.d0:.0f}} counts, D3 - D0 = {{m.d3 - m.d0:.0f}}')")
SQUARE_SCRIPT = ("1000 LOAD\n1100 LOAD\nSet.Up.Robot\nSquare\n"
                 "0 Read.Counter . 1 Read.Counter .\n")

# exercise -> (files to write in the scratch directory, commands); {tmp} is the
# scratch directory, {disk} the copy of the lab's disk
CHECKS = {
    1: ({"d2.script": D2_SCRIPT},
        [HARNESS + ("run", "{tmp}/d2.script", "--out", "{tmp}"),
         (sys.executable, "-c", D2_MEASURE)]),
    2: ({}, [HARNESS + ("tick", "--ticks", "8"),
             HARNESS + ("tick", "--ticks", "8", "--setup", "1000 LOAD", "--setup", "1030 LOAD",
                        "--setup", "Set.Up.Robot Ramp.Servo")]),
    3: ({}, [HARNESS + ("tick", "--ticks", "16", "--line", "800 0 400 0 Abs.Move Move.Complete?"),
             HARNESS + ("tick", "--ticks", "16", "--line", "0 800 400 0 Abs.Move Move.Complete?")]),
    4: ({}, [HARNESS + ("timing", "--servo", "idle")]),
    5: ({"square.script": SQUARE_SCRIPT},
        [HARNESS + ("run", "{tmp}/square.script", "--disk", "{disk}", "--out", "{tmp}")]),
}
# what a check measured that its commands leave in a file: the end of it is shown
SHOWN_FILES = {5: ("square.transcript", 4)}     # the counters: about 0 0


def shown(command):
    """A command as the reader would type it (python -m harness ..., in /tmp/ex)."""
    words = ["python" if w == sys.executable else
             w.format(tmp="/tmp/ex", disk=f"/tmp/ex/{DISK_COPY}")
             for w in command]
    return " ".join(w if w and " " not in w and "\n" not in w else f'"{w}"' for w in words)


def tail(text, lines=SHOWN_LINES):
    rows = text.rstrip("\n").splitlines()
    return "\n".join((["..."] if len(rows) > lines else []) + rows[-lines:])


async def run_check(exercise, disk):
    """(ok, text): each command of the exercise's check and what it printed."""
    files, commands = CHECKS[exercise]
    out, ok = [], True
    with tempfile.TemporaryDirectory(prefix=f"lab-check-{exercise}-") as tmp:
        copy = Path(tmp) / DISK_COPY
        shutil.copyfile(disk, copy)                 # the lab's disk is never written here
        for name, text in files.items():
            (Path(tmp) / name).write_text(text)
        for command in commands:
            argv = [w.format(tmp=tmp, disk=copy) for w in command]
            out.append(f"$ {shown(command)}")
            proc = await asyncio.create_subprocess_exec(
                *argv, cwd=ROOT, stdin=asyncio.subprocess.DEVNULL,
                stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.STDOUT)
            try:
                printed, _ = await asyncio.wait_for(proc.communicate(), TIMEOUT_S)
            except asyncio.TimeoutError:
                proc.kill()
                await proc.wait()
                out.append(f"stopped after {TIMEOUT_S} s")
                return False, "\n".join(out)
            out.append(tail(printed.decode("utf-8", "replace").replace(tmp, "/tmp/ex")))
            if proc.returncode:
                out.append(f"exit status {proc.returncode}")
                ok = False
                break
        if exercise in SHOWN_FILES:
            name, lines = SHOWN_FILES[exercise]
            path = Path(tmp) / name
            if path.is_file():
                out.append(f"the end of /tmp/ex/{name}:")
                out.append(tail(path.read_text(errors="replace"), lines))
    return ok, "\n".join(out)
