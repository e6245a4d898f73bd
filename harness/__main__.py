"""`python -m harness ...`: the project's command line (see harness/cli.py).

The harness needs the pinned packages of requirements.txt, which `make venv` installs
in .venv. Started by a Python that lacks them (the system's, outside the venv), it
runs itself again with .venv's Python, so `python -m harness` works from any shell
in the repository; with no .venv yet it says how to make one.
"""
import os
import sys
from importlib.util import find_spec
from pathlib import Path

VENV_PYTHON = Path(__file__).resolve().parent.parent / ".venv" / "bin" / "python"
PINNED = ("numpy", "matplotlib", "pexpect", "aiohttp")     # looked up, not imported: cheap


def missing_package():
    return next((name for name in PINNED if find_spec(name) is None), None)


if __name__ == "__main__":
    missing = missing_package()
    if missing:
        if VENV_PYTHON.exists() and Path(sys.prefix) != VENV_PYTHON.parent.parent:   # not in it yet
            os.execv(VENV_PYTHON, [str(VENV_PYTHON), "-m", "harness", *sys.argv[1:]])
        sys.exit(f"python -m harness: this Python ({sys.executable}) lacks {missing}, one of "
                 "the harness's pinned packages: run `make venv` first (it creates .venv), "
                 "then `python -m harness` again (it uses .venv by itself)")
    from harness.cli import main
    sys.exit(main())
