"""The host assembler: forth/asm.fs under gforth, through tests/asm/host-driver.fs."""
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from .corpus import ORIGIN, forth_for_host

ROOT = Path(__file__).resolve().parents[2]
DRIVER = ROOT / "tests" / "asm" / "host-driver.fs"


@dataclass(frozen=True)
class Result:
    words: tuple      # words assembled at ORIGIN, empty after an error
    error: str = ""   # the abort message, empty when the unit assembled
    emitted: int = 0  # words emitted before an error (must be 0: nothing half-done)


def assemble(forth_texts, origin=ORIGIN, timeout=60):
    """Assemble each FORTH text as one unit at origin; one gforth run for all."""
    lines = [f"{origin} origin !"]
    for text in forth_texts:
        host = forth_for_host(text)
        if '"' in host:
            raise ValueError(f"a unit cannot contain a double quote: {text!r}")
        lines.append(f's" {host}" unit')
    with tempfile.NamedTemporaryFile("w", suffix=".fs", delete=False) as f:
        f.write("\n".join(lines) + "\nbye\n")
        script = f.name
    try:
        proc = subprocess.run(["gforth", str(DRIVER), script], capture_output=True,
                              text=True, timeout=timeout, cwd=DRIVER.parent)
    finally:
        Path(script).unlink()
    out = [l for l in proc.stdout.splitlines() if l.startswith(("ok", "error"))]
    if proc.returncode or len(out) != len(forth_texts):
        raise RuntimeError(f"gforth host driver failed (rc {proc.returncode}):\n"
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
