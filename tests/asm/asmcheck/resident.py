"""The resident ASSEMBLER on the emulated 11/23: the same corpus, on the machine.

The units travel on the RL02 disk, as the appendix's blocks will: packed into
blocks and LOADed with one console line, each unit printing `U:` and its words
in octal. A unit that must fail gets a block of its own, so that its error ends
only its own LOAD; `EMITTED?` then tells how many words it left.
"""
import re
import shutil
import subprocess
from pathlib import Path

from harness.blocks import disk
from harness.machine.build import KERNEL, ROOT
from harness.machine.machine import Machine

BUILD_FS = ROOT / "forth" / "meta" / "build.fs"
DRIVER = ROOT / "tests" / "asm" / "resident-driver.fs"
TARGET_INCLUDE = 's" forth/asm-target.fs" kernel'
BOOT_LINE = 's" forth/kernel/boot.fs" kernel'
BLOCK = disk.BLOCK_BYTES
DRIVER_BLOCK, CORPUS_BLOCK, ERROR_BLOCK = 100, 101, 300


def resident_kernel(tmp):
    """build/kernel.lda when the kernel build already reads forth/asm-target.fs;
    otherwise the same build with that one line added, made in tmp."""
    source = BUILD_FS.read_text()
    if "asm-target.fs" in source:
        return KERNEL
    if BOOT_LINE not in source:
        raise RuntimeError(f"cannot place the assembler in {BUILD_FS}: no {BOOT_LINE!r}")
    tmp = Path(tmp)
    shutil.copytree(ROOT / "forth", tmp / "forth")
    (tmp / "forth" / "meta" / "build.fs").write_text(
        source.replace(BOOT_LINE, f"{TARGET_INCLUDE}\n{BOOT_LINE}"))
    (tmp / "build").mkdir()
    proc = subprocess.run(["gforth", "forth/meta/build.fs", "-e", "bye"], cwd=tmp,
                          capture_output=True, text=True, timeout=120,
                          stdin=subprocess.DEVNULL)
    if proc.returncode:
        raise RuntimeError(f"kernel with the resident assembler did not build:\n"
                           f"{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}")
    return tmp / "build" / "kernel.lda"


def _pack(texts):
    """Texts as block contents: whole tokens, each block at most 1024 bytes."""
    blocks, current = [], ""
    for token in " ".join(texts).split():
        if len(current) + len(token) + 1 > BLOCK:
            blocks.append(current)
            current = ""
        current += token + " "
    return blocks + [current]


def _disk(path, placed):
    """An RL02 image holding {block number: text}."""
    blocks = {}
    for number, text in placed.items():
        data = text.encode("ascii")
        if len(data) > BLOCK:
            raise ValueError(f"block {number} overflows: {text[:60]!r}")
        blocks[number] = data.ljust(BLOCK)
    Path(path).write_bytes(disk.pack(blocks))
    return path


def _unit(forth):
    return f"ASSEMBLER UNIT{{ {forth} }}UNIT"


def _words(text):
    return [tuple(int(w, 8) for w in line[2:].split())
            for line in text.replace("\r", "").split("\n") if line.startswith("U:")]


def assemble(good, bad, tmp):
    """Assemble FORTH texts on the machine. good: a list of words per text;
    bad: (error message, words emitted before it) per text."""
    tmp = Path(tmp)
    kernel = resident_kernel(tmp / "kernel")
    corpus = _pack(_unit(t) for t in good)
    placed = {DRIVER_BLOCK: " ".join(DRIVER.read_text().split())}
    placed.update({CORPUS_BLOCK + i: b for i, b in enumerate(corpus)})
    if CORPUS_BLOCK + len(corpus) > ERROR_BLOCK:
        raise ValueError("the corpus outgrew its blocks")
    placed.update({ERROR_BLOCK + i: _unit(t) for i, t in enumerate(bad)})
    image = _disk(tmp / "corpus.dsk", placed)
    with Machine(disk=image, kernel=kernel, timeout=120) as m:
        m.send(f"{DRIVER_BLOCK} LOAD")
        words = _words(m.send(f"{CORPUS_BLOCK} {CORPUS_BLOCK + len(corpus) - 1} THRU"))
        errors = []
        for i in range(len(bad)):
            reply = m.reply(f"{ERROR_BLOCK + i} LOAD")
            emitted = int(m.send("EMITTED?").split()[0])
            errors.append((reply.error if not reply.ok else "no error: " + reply.output,
                           emitted))
    if len(words) != len(good):
        raise RuntimeError(f"the machine answered {len(words)} of {len(good)} units")
    return words, errors
