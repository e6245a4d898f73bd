"""`python -m harness ARGV` run in the test's own process: harness.cli.main, what
harness/__main__.py calls, with stdout and stderr caught, and the result as
subprocess.run gives it (returncode, stdout, stderr), a usage error's exit as its
status. A command-line test module keeps one real `python -m harness` subprocess
for the start itself (the venv re-exec, __main__); its other tests need not pay a
Python's start each (about 0.1 CPU-s, a hundred times in make test)."""
import contextlib
import io
import subprocess

from harness.cli import main


def harness_here(*args):
    argv = [str(a) for a in args]
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv)
        except SystemExit as exit_:                 # argparse: --help 0, usage 2
            status = 0 if exit_.code is None else exit_.code
    return subprocess.CompletedProcess(["python", "-m", "harness", *argv], status,
                                       out.getvalue(), err.getvalue())
