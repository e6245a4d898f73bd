"""`make help` lists every phony target of the Makefile and mk/*.mk with its
description (the `## ...` after the target)."""
import re
import subprocess

from harness.machine.build import ROOT


def test_make_help_names_every_phony_target():
    sources = [ROOT / "Makefile", *sorted((ROOT / "mk").glob("*.mk"))]
    phony = {t for path in sources for line in path.read_text().splitlines()
             if line.startswith(".PHONY:") for t in line.split()[1:]}
    shown = subprocess.run(["make", "-s", "help"], cwd=ROOT, capture_output=True, text=True,
                           timeout=60).stdout
    listed = dict(re.findall(r"^  make (\S+) +(\S.*)$", shown, re.M))
    assert phony - set(listed) == set(), "give these targets a ## description"
    assert all(len(text) > 8 for text in listed.values())
