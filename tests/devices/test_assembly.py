"""Every hand-assembled program of these tests disassembles, by SIMH's own
EXAMINE -M, to the text it was written as."""
import pytest

from harness import simh
from programs import all_programs


@pytest.mark.parametrize("name", sorted(all_programs()))
def test_program_words_match_their_text(name):
    prog = all_programs()[name]
    listing = prog.all_listing()
    script = prog.script(start=False) + "".join(f"examine -m {a:o}\n" for a, _ in listing)
    out = simh.run(script)
    got = [(int(m.split(":\t")[0], 8), m.split(":\t")[1].strip())
           for m in out.splitlines() if ":\t" in m and not m.startswith(("SP", "PSW", "PC"))]
    assert got == listing
