"""Reference (a): pdpy11, a PDP-11 cross assembler from PyPI, on the MACRO-11 side."""
import re

from pdpy11 import parser, reports
from pdpy11.compiler import Compiler

from .corpus import ORIGIN

BRANCHES = {"BR", "BNE", "BEQ", "BGE", "BLT", "BGT", "BLE", "BPL", "BMI", "BHI",
            "BLOS", "BVC", "BVS", "BCC", "BCS", "BHIS", "BLO"}
ABSOLUTE = re.compile(r"^[0-7]+$")


class ReferenceError(Exception):
    """pdpy11 rejected a statement."""


class _Collect:
    """A pdpy11 report handler that keeps the messages instead of printing them."""
    def __init__(self):
        self.messages = []

    def __call__(self, priority, identifier, *found):
        self.messages += [f"{identifier}: {text}" for _start, _end, text in found]


def _label_relative(statement):
    """pdpy11 reads a bare number as a branch target as a local label: write it
    as an offset from the label Z at ORIGIN instead."""
    parts = statement.split(None, 1)
    if len(parts) < 2:
        return statement
    mnemonic, operands = parts[0].upper(), parts[1]
    ops = [o.strip() for o in operands.split(",")]
    index = {"SOB": 1}.get(mnemonic, 0 if mnemonic in BRANCHES else None)
    if index is None or index >= len(ops) or not ABSOLUTE.match(ops[index]):
        return statement
    delta = int(ops[index], 8) - ORIGIN
    ops[index] = f"Z+{delta:o}" if delta >= 0 else f"Z-{-delta:o}"
    return f"{mnemonic} {','.join(ops)}"


def assemble(statements):
    """The 16-bit words pdpy11 assembles for the statements, placed at ORIGIN."""
    return assemble_source(f".LINK {ORIGIN:o}\nZ:\n" +
                           "\n".join(_label_relative(s) for s in statements) + "\n")


def assemble_source(text, origin=ORIGIN):
    """The words of a whole MACRO-11 source that places itself (.LINK) at origin."""
    handler = _Collect()
    try:
        with reports.handle_reports(handler):
            parsed = parser.parse("corpus", text)
            base, code = Compiler().compile_and_link_files([parsed])
    except reports.UnrecoverableError:
        base = None
    if handler.messages or base != origin:
        raise ReferenceError(f"pdpy11: {handler.messages or f'placed at {base}'}\n{text[:300]}")
    return [code[i] | code[i + 1] << 8 for i in range(0, len(code), 2)]
