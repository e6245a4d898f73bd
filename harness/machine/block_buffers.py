"""Which blocks the FORTH holds UPDATEd and not yet written, read from a stopped
machine: what the console reports when FLUSH could not write them.

The kernel (forth/kernel/disk.fs) keeps two CREATEd tables of #BUFS = 4 cells:
BUF-BLK (the block in each buffer, -1 = none) and BUF-UPD (true when UPDATEd).
build/kernel.map gives their code fields; the data start 4 bytes on (>BODY).
SIMH's EXAMINE prints them as "address:<tab>octal" lines. Pure logic apart from
`examine`, which the caller supplies (one SIMH command -> its output).
"""
from harness.machine.kernel_layout import BODY
from harness.machine.simh import examined_all

BUFS = 4                      # forth/kernel/disk.fs #BUFS: its tables have 4 cells


def table_command(symbols, name):
    """The EXAMINE command that prints the #BUFS cells of table `name`."""
    first = symbols[name] + BODY
    return f"examine {first:o}:{first + 2 * (BUFS - 1):o}"


def unwritten(blocks, updated):
    """Block numbers held UPDATEd: `blocks` and `updated` are the tables' cells."""
    return sorted(b for b, u in zip(blocks, updated) if u and b != 0o177777)


def read_unwritten(symbols, examine):
    """The UPDATEd, unwritten blocks, or None when the tables cannot be read."""
    cells = [[v for _, v in examined_all(examine(table_command(symbols, name)))]
             for name in ("BUF-BLK", "BUF-UPD")]
    if any(len(c) != BUFS for c in cells):
        return None
    return unwritten(*cells)
