"""Every hand-assembled program of these tests disassembles, by SIMH's own
EXAMINE -M, to the text it was written as."""
import pytest

from harness.analysis.pdp11prog import check_listing
from programs import all_programs


@pytest.mark.parametrize("name", sorted(all_programs()))
def test_program_words_match_their_text(name):
    assert check_listing(all_programs()[name]) == []
