"""FLUSH is durable: a short version of make soak-disk (harness/soak/disk_soak.py), and
the write-through's failure path (an fsync that fails is a FORTH error)."""

import pytest

from harness.soak import disk_soak
from harness.machine.build import fresh_disk
from harness.machine.machine import ForthError, Machine
from tests.run.common import failing_fsync_library, needs_build

@needs_build
def test_flushed_blocks_survive_kill_9(tmp_path):
    image = fresh_disk(tmp_path, "soak.dsk")
    tally = disk_soak.soak(image, 10)
    # cycles 5 and 10 kill during FLUSH: 8 x 2 confirmed blocks, 8 + 2 x 2 unconfirmed
    assert tally.cycles == 10 and tally.flushed == 16 and tally.unconfirmed == 12
    assert tally.lost == [] and tally.corrupted == [], disk_soak.report(tally)


def test_compare_tells_lost_from_corrupted_and_allows_unconfirmed_writes():
    base = bytes(5 * 1024)
    model = {None: base, 1: b"a" * 1024}
    image = bytearray(base)
    image[2048:3072] = b"b" * 1024           # block 2: neither flushed nor pending
    image[3072:4096] = b"c" * 1024           # block 3: an unconfirmed block's new contents
    image[4096:4608] = b"d" * 512            # block 4: unconfirmed, and torn in half
    tally = disk_soak.Tally()
    disk_soak.compare(bytes(image), model, {1: b"a" * 1024},
                      {3: b"c" * 1024, 4: b"d" * 1024}, 7, tally)
    assert tally.lost == [(7, 1)] and tally.corrupted == [(7, 2), (7, 4)]
    assert tally.unconfirmed_kept == 1
    assert model[1] == bytes(1024)            # the model follows: counted once
    again = disk_soak.Tally()
    disk_soak.compare(bytes(image), model, {}, {}, 8, again)
    assert again.lost == again.corrupted == []


def test_each_cycle_writes_new_contents():
    assert disk_soak.block_contents(1, 3000) != disk_soak.block_contents(2, 3000)
    assert disk_soak.block_contents(95, 3000)[:2] == (95).to_bytes(2, "little")
    edited, pending = disk_soak.cycle_blocks(3)
    assert pending not in edited and len(set(edited)) == disk_soak.EDITS_PER_CYCLE


@needs_build
def test_a_failed_fsync_is_a_write_error_not_ok(tmp_path, monkeypatch):
    monkeypatch.setenv("LD_PRELOAD", str(failing_fsync_library()))
    image = fresh_disk(tmp_path, "eio.dsk")
    with Machine(disk=image) as m:
        with pytest.raises(ForthError) as err:
            m.send("3000 BLOCK DROP UPDATE FLUSH")
        assert "RL0 block 3000 write failed" in err.value.output
        assert "drive-error" in err.value.output
        assert "write-data-error" in err.value.output
        assert m.send("1 2 + .") == "3 "             # the FORTH goes on
