"""The host assembler: forth/asm.fs under gforth (tests/asm/host-*.fs).

Two ways to run it: as the metacompiler does (64-bit gforth cells), and with
16-bit cell arithmetic (tests/asm/sixteen.fs plus a copy of asm.fs whose
literals are 16-bit), which is how the PDP-11 will run the same source as the
resident ASSEMBLER."""
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from .corpus import ORIGIN, forth_for_host

ROOT = Path(__file__).resolve().parents[2]
FORTH = ROOT / "forth"
TESTS = ROOT / "tests" / "asm"
INTEGER = re.compile(r"(?<!\S)(-?\d+)(?!\S)")


@dataclass(frozen=True)
class Result:
    words: tuple      # words assembled at the origin, empty after an error
    error: str = ""   # the abort message, empty when the unit assembled
    emitted: int = 0  # words emitted before an error (of earlier instructions)


def sixteen_bit_copy(directory):
    """asm.fs and its loader in directory, every literal as the PDP-11 holds it."""
    def narrow(m):
        n = int(m.group(1)) & 0xFFFF
        return str(n - 0x10000 if n > 0x7FFF else n)
    text = (FORTH / "asm.fs").read_text()
    (Path(directory) / "asm.fs").write_text(INTEGER.sub(narrow, text))
    shutil.copy(FORTH / "asm-host.fs", directory)
    return Path(directory) / "asm-host.fs"


def assemble(forth_texts, origin=ORIGIN, sixteen=False, timeout=60):
    """Assemble each FORTH text as one unit at origin; one gforth run for all."""
    lines = [f"{origin} origin !"]
    for text in forth_texts:
        host = forth_for_host(text)
        if '"' in host:
            raise ValueError(f"a unit cannot contain a double quote: {text!r}")
        lines.append(f's" {host}" unit')
    with tempfile.TemporaryDirectory() as tmp:
        script = Path(tmp) / "units.fs"
        script.write_text("\n".join(lines) + "\nbye\n")
        if sixteen:
            loader = [str(TESTS / "sixteen.fs"), str(sixteen_bit_copy(tmp)), "-e", "previous"]
        else:
            loader = [str(FORTH / "asm-host.fs")]
        command = ["gforth", str(TESTS / "host-image.fs"), *loader,
                   str(TESTS / "host-units.fs"), str(script)]
        proc = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                              stdin=subprocess.DEVNULL)
    out = [l for l in proc.stdout.splitlines() if l.startswith(("ok", "error"))]
    if proc.returncode or len(out) != len(forth_texts):
        raise RuntimeError(f"gforth host assembler failed (rc {proc.returncode}):\n"
                           f"{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}")
    results = []
    for line in out:
        kind, _, rest = line.partition(" ")
        if kind == "ok":
            results.append(Result(tuple(int(w, 8) for w in rest.split())))
        else:
            count, _, message = rest.partition(" ")
            results.append(Result((), message.strip(), int(count)))
    return results
