"""Reference (a): pdpy11, a PDP-11 cross assembler from PyPI, on the MACRO-11 side."""
import re

from pdpy11 import parser, reports
from pdpy11.compiler import Compiler
from pdpy11.deferred import wait
from pdpy11.types import Label

from .corpus import ORIGIN

# a bare octal number (or @ and one) is an address: a branch target or a
# PC-relative operand; these instructions' numbers are only numbers
NOT_ADDRESSES = {"EMT", "TRAP", "MARK", "SPL"}
ADDRESS = re.compile(r"^(@?)([0-7]+)$")


class ReferenceError(Exception):
    """pdpy11 rejected a statement."""


class _Collect:
    """A pdpy11 report handler that keeps the messages instead of printing them."""
    def __init__(self):
        self.messages = []

    def __call__(self, priority, identifier, *found):
        self.messages += [f"{identifier}: {text}" for _start, _end, text in found]


def _relative_to(label, statement):
    """The statement with each address written as an offset from `label`, which
    stands where ORIGIN would: pdpy11 reads a bare number as a branch target as a
    local label, and a unit need not be placed at ORIGIN (assemble_each)."""
    parts = statement.split(None, 1)
    if len(parts) < 2 or parts[0].upper() in NOT_ADDRESSES:
        return statement

    def relative(operand):
        address = ADDRESS.match(operand.strip())
        if not address:
            return operand.strip()
        return f"{address.group(1)}{label}{int(address.group(2), 8) - ORIGIN:+o}"
    return f"{parts[0]} {','.join(map(relative, parts[1].split(',')))}"


def assemble(statements):
    """The 16-bit words pdpy11 assembles for the statements, placed at ORIGIN."""
    return assemble_source(f".LINK {ORIGIN:o}\nZ:\n" +
                           "\n".join(_relative_to("Z", s) for s in statements) + "\n")


def assemble_each(units):
    """assemble() of each unit (a list of statements): its words, or the
    ReferenceError pdpy11's messages make. All of them in one source, each unit
    after its own label (one parse and link: one per unit costs twice the CPU for
    the corpus's 1 100 units); one by one only when pdpy11 refuses something, to
    tell which unit."""
    labels = [f"U{i}" for i in range(len(units))] + ["UEND"]
    text = "".join(f"{label}:\n" + "".join(_relative_to(label, s) + "\n" for s in unit)
                   for label, unit in zip(labels, units))
    try:
        words, symbols = _assemble(f".LINK {ORIGIN:o}\n{text}{labels[-1]}:\n")
    except ReferenceError:
        return [_words_or_error(unit) for unit in units]
    at = [(symbols[label] - ORIGIN) // 2 for label in labels]
    return [words[a:b] for a, b in zip(at, at[1:])]


def _words_or_error(statements):
    try:
        return assemble(statements)
    except ReferenceError as e:
        return e


def assemble_source(text, origin=ORIGIN):
    """The words of a whole MACRO-11 source that places itself (.LINK) at origin."""
    return _assemble(text, origin)[0]


def _assemble(text, origin=ORIGIN):
    """(words, label -> address) of a MACRO-11 source placed (.LINK) at origin."""
    handler = _Collect()
    try:
        with reports.handle_reports(handler):
            parsed = parser.parse("corpus", text)
            compiler = Compiler()
            base, code = compiler.compile_and_link_files([parsed])
    except reports.UnrecoverableError:
        base = None
    if handler.messages or base != origin:
        raise ReferenceError(f"pdpy11: {handler.messages or f'placed at {base}'}\n{text[:300]}")
    return ([code[i] | code[i + 1] << 8 for i in range(0, len(code), 2)],
            {label.name: wait(value) for _, (label, value) in compiler.symbols.items()
             if isinstance(label, Label)})
