"""build/kernel.map as the harness reads it (harness/machine/kernel_layout.py)."""
import pytest

from harness.machine.build import KERNEL_MAP
from harness.machine.kernel_layout import CHAINS, KernelMapError, read_kernel_map


def test_a_map_with_another_chain_count_is_refused(tmp_path):
    """Issue 19: the harness walks a word list's chains (kernel_layout.CHAINS); a
    kernel metacompiled with another #chains is refused by name, not misread."""
    assert read_kernel_map(KERNEL_MAP)["#CHAINS"] == CHAINS
    other = tmp_path / "kernel.map"
    other.write_text(f"{CHAINS // 4:06o} #CHAINS\n002000 DOCOL\n")
    with pytest.raises(KernelMapError, match=f"into {CHAINS // 4} chains per word list"):
        read_kernel_map(other)
