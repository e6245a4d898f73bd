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

from harness.machine.build import ROOT

from .corpus import ORIGIN, forth_for_host

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


def gforth(loader, script, timeout=60):
    """Run gforth on the host image, the loader files and then the script text
    (which must end with bye); its standard output."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "script.fs"
        path.write_text(script)
        command = ["gforth", str(TESTS / "host-image.fs"), *loader(tmp),
                   str(TESTS / "host-units.fs"), str(path)]
        proc = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                              stdin=subprocess.DEVNULL)
    if proc.returncode:
        raise RuntimeError(f"gforth host assembler failed (rc {proc.returncode}):\n"
                           f"{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}")
    return proc.stdout


def host_loader(tmp):
    """Loader files for the assembler with gforth's own cells."""
    return [str(FORTH / "asm-host.fs")]


def sixteen_loader(tmp):
    """Loader files for the assembler with 16-bit cell arithmetic."""
    return [str(TESTS / "sixteen.fs"), str(sixteen_bit_copy(tmp)), "-e", "previous"]


def assemble(forth_texts, origin=ORIGIN, sixteen=False, timeout=60):
    """Assemble each FORTH text as one unit at origin; one gforth run for all."""
    lines = [f"{origin} origin !"]
    for text in forth_texts:
        host = forth_for_host(text)
        if '"' in host:
            raise ValueError(f"a unit cannot contain a double quote: {text!r}")
        lines.append(f's" {host}" unit')
    stdout = gforth(sixteen_loader if sixteen else host_loader,
                    "\n".join(lines) + "\nbye\n", timeout)
    out = [l for l in stdout.splitlines() if l.startswith(("ok", "error"))]
    if len(out) != len(forth_texts):
        raise RuntimeError(f"gforth answered {len(out)} of {len(forth_texts)} units:\n"
                           f"{stdout[-2000:]}")
    results = []
    for line in out:
        kind, _, rest = line.partition(" ")
        if kind == "ok":
            results.append(Result(tuple(int(w, 8) for w in rest.split())))
        else:
            count, _, message = rest.partition(" ")
            results.append(Result((), message.strip(), int(count)))
    return results
