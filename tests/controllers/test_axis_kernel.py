"""The FORTH kernel built for the LSI-11/03 (forth/meta/build-1103.fs): the
11/23's image with ENTRY's memory-management setup branched over and the banner's
machine name, nothing else; on SIMH's 11/03 it boots and runs what the per-axis
servo needs (EIS arithmetic, the console, the disk, traps reported, the KW11-L)."""
from harness.machine.build import KERNEL, KERNEL_1103
from harness.machine.kernel_layout import read_kernel_map

from axis1103 import lsi11  # noqa: F401  (fixture)

BR = 0o000400          # BR with a zero offset; the offset is the low byte (words)


def loaded_bytes(path):
    """address -> byte of an absolute-loader file (checksums verified), start."""
    data, mem, pos = path.read_bytes(), {}, 0
    while True:
        count = data[pos + 2] | data[pos + 3] << 8
        addr = data[pos + 4] | data[pos + 5] << 8
        if count == 6:
            return mem, addr
        assert sum(data[pos:pos + count + 1]) % 256 == 0, f"{path}: checksum at {pos}"
        mem.update({addr + i: b for i, b in enumerate(data[pos + 6:pos + count])})
        pos += count + 1


def test_1103_image_is_the_1123_image_but_the_mmu_branch_and_the_name():
    m23, start23 = loaded_bytes(KERNEL)
    m03, start03 = loaded_bytes(KERNEL_1103)
    assert start03 == start23 and m03.keys() == m23.keys()
    differ = sorted(a for a in m23 if m23[a] != m03[a])
    sym = read_kernel_map()
    branch = [a for a in differ if sym["ENTRY"] <= a < sym["ENTRY"] + 0o200]
    name = [a for a in differ if a not in branch]
    # one BR in ENTRY, over the MMU setup (its first word was MOV #KIPDR,R0) ...
    at = branch[0]
    assert branch in ([at], [at, at + 1]) and at % 2 == 0
    word = m03[at] | m03[at + 1] << 8
    assert word & 0o177400 == BR and 10 < word & 0o377 < 64
    assert m23[at] | m23[at + 1] << 8 == 0o012700          # MOV #n,R0
    assert m23[at + 2] | m23[at + 3] << 8 == 0o172300      # n = KIPDR
    # ... and "PDP-11/23" -> "PDP-11/03" in BANNER
    assert len(name) == 1 and chr(m23[name[0]]) == "2" and chr(m03[name[0]]) == "0"
    assert bytes(m03[name[0] - 7 + i] for i in range(9)) == b"PDP-11/03"


def test_1103_boots_and_runs_the_basics(lsi11):
    m = lsi11()
    assert "PDP-11/03 FORTH" in m.banner
    assert m.send("7 -3 * .  -7 2 / .  1000 7 /MOD . .  100 200 M* D.") == "-21 -3 142 6 20000 "  # symmetric division, as on the 11/23
    assert m.send("60000 0 7 UM/MOD . .  HEX 1234 . DECIMAL") == "8571 3 1234 "
    # a bus error (no memory at 160000) is reported at the prompt, dictionary intact
    ok, out, error = m.reply(": PEEK 160000O @ ;  PEEK")
    assert not ok and error.startswith("bus error or odd address (vector 000004")
    assert m.send("' PEEK CATCH .") == "-256 "
    # no MMU on the 11/03: an underflow is caught by the interpreter's depth check
    ok, out, error = m.reply("DROP")
    assert not ok and "stack underflow" in error
    # the disk: blocks load (the 11/03's own servo's)
    m.send("1080 LOAD")
    assert m.send("Range ? Delay ?") == "5 30 "
    # the KW11-L ticks at 60 Hz of simulated time (the kernel's TICK counts them)
    low = read_kernel_map()["TICKS"] + 2
    before = m.examine(low)
    m.send("100O 177546O !")          # its interrupt on (the kernel leaves it off)
    m.idle(1.0)
    assert 59 <= m.examine(low) - before <= 61
