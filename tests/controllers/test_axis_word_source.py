"""The per-axis blocks share their names with the 1983 blocks (blocks 1080-1089
derive from 1000-1008; 1200-1206 keep the paper's user interface), so the lab's
program pane, which finds a stopped word's definition by its neighbours in the
dictionary (harness/lab/word_source.py, three each side), must still tell them
apart: each word of each machine's load is placed in its own block."""
import pytest

from harness.lab.program_pane import written_blocks
from harness.lab.word_source import definition_among, definitions
from harness.machine.build import PRISTINE_DISK

NEIGHBOURS = 3           # as the lab server asks (front_panel.neighbours)
LOADS = {"the 11/23's 1983 servo": range(1000, 1013),
         "an 11/03's servo": range(1080, 1090),
         "the 11/23's link words": range(1200, 1207)}


@pytest.fixture(scope="module")
def blocks():
    """The pristine disk's written blocks, read once for the three loads."""
    return list(written_blocks(PRISTINE_DISK))


@pytest.mark.parametrize("load", LOADS)
def test_each_word_of_a_load_is_placed_in_its_own_blocks(load, blocks):
    found = definitions(blocks)
    loaded = [d for d in found if d[1] in LOADS[load]]                 # dictionary order
    names = [n for n, _, _ in loaded]
    wrong = []
    for i, (name, block, line) in enumerate(loaded):
        before = names[max(0, i - NEIGHBOURS):i][::-1]
        after = names[i + 1:i + 1 + NEIGHBOURS]
        placed = definition_among(name, found, before, after)
        if placed != (block, line):
            wrong.append((name, block, placed))
    assert not wrong, wrong
