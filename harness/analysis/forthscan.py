"""Read FORTH blocks the way LOAD does, without running them (pure logic).

LOAD interprets a block as one 1024-character string: lines have no ends, so a
comment may run over several lines and a 64-character line runs into the next.
check_load() follows `-->` from block to block and reports every word that is
neither a number, nor defined earlier in the load, nor in the kernel's word lists;
assembler words used outside the ASSEMBLER vocabulary; definitions that do not
close; and unbalanced control structures.  It knows only the defining and
vocabulary words the appendix uses.
"""
import re
from dataclasses import dataclass

from harness.blocks.blockfile import WIDTH

DEFINERS = {":", "CODE", "CON", "VAR", "ARRAY"}     # each takes the next word as a name
_PARSED = {"(": ")", ".(": ")", '."': '"'}   # words that parse text up to a delimiter
_NUMBER = re.compile(r"^-?(\d+|[0-7]+O)$", re.IGNORECASE)
# Control structures: opener -> its closers; middles allowed in between.
_FORTH_FLOW = {"BEGIN": ({"END", "UNTIL"}, set()), "DO": ({"LOOP", "+LOOP"}, set()),
               "IF": ({"THEN"}, {"ELSE"})}
_ASM_FLOW = {"BEGIN,": ({"END,", "UNTIL,"}, set()), "IF,": ({"THEN,"}, {"ELSE,"})}


@dataclass(frozen=True)
class Word:
    text: str
    block: int
    line: int           # 0-15: where the word starts

    def __str__(self):
        return f"block {self.block} line {self.line}: {self.text}"


def is_number(text):
    """A literal the kernel converts: decimal, or octal with a trailing O."""
    return bool(_NUMBER.match(text))


def words(block, number):
    """The words LOAD sees in a 1024-byte block, comments and the text of `."` and
    `.(` left out; stops after `;S` or `-->`.  A `(` with no `)` in the block comes
    out as the word '( without )'."""
    text = block.decode("ascii")
    found, pos = [], 0
    while True:
        match = re.compile(r"\S+").search(text, pos)
        if not match:
            return found
        token, pos = match.group(), match.end()
        if token in _PARSED:
            close = text.find(_PARSED[token], pos + 1)
            if close < 0:
                found.append(Word(f"{token} without {_PARSED[token]}", number,
                                  match.start() // WIDTH))
                return found
            pos = close + 1
            if token == "(":
                continue
        found.append(Word(token, number, match.start() // WIDTH))
        if token in ("-->", ";S"):
            return found


class _Load:
    def __init__(self, kernel_forth, kernel_asm):
        self.forth = {w.upper() for w in kernel_forth}
        self.asm = {w.upper() for w in kernel_asm}
        self.defined = []           # names the load defines, in order
        self.defined_upper = set()
        self.context = "FORTH"
        self.compiling = None       # the Word whose definition is open
        self.flow = []              # open control structures (Word)
        self.problems = []

    def problem(self, word, message):
        self.problems.append(f"block {word.block} line {word.line}: {message}")

    def known(self, name):
        upper = name.upper()
        if upper in self.forth or upper in self.defined_upper:
            return True
        return self.context == "ASSEMBLER" and upper in self.asm

    def close_definition(self, word):
        for opened in self.flow:
            self.problem(opened, f"{opened.text} not closed before {word.text}")
        self.flow = []
        self.compiling = None

    def control(self, word):
        table = _ASM_FLOW if self.context == "ASSEMBLER" else _FORTH_FLOW
        upper = word.text.upper()
        if upper in table:
            self.flow.append(word)
            return
        for opener, (closers, middles) in table.items():
            if upper in closers | middles:
                if not self.flow or self.flow[-1].text.upper() != opener:
                    self.problem(word, f"{word.text} without {opener}")
                elif upper in closers:
                    self.flow.pop()

    def step(self, word, following):
        upper = word.text.upper()
        if upper in DEFINERS:
            if self.compiling is not None and self.compiling.text.upper() != "CODE":
                self.problem(word, f"{word.text} inside the definition opened at "
                                   f"block {self.compiling.block} line {self.compiling.line}"
                                   " (a missing ;)")
            if self.compiling is not None:
                self.close_definition(word)
            name = next(following, None)
            if name is None:
                self.problem(word, f"{word.text} without a name")
                return
            self.defined.append(name.text)
            self.defined_upper.add(name.text.upper())
            if upper in (":", "CODE"):
                self.compiling = word
                self.context = "FORTH" if upper == ":" else "ASSEMBLER"
            return
        if upper == ";":
            if self.compiling is None:
                self.problem(word, "; outside a definition")
            self.close_definition(word)
            return
        if upper in ("FORTH", "ASSEMBLER"):
            self.context = upper
            return
        if upper in ("-->", ";S") or is_number(word.text):
            return
        if not self.known(word.text):
            where = " (an assembler word outside ASSEMBLER)" if upper in self.asm else ""
            self.problem(word, f"{word.text} is not defined{where}")
            return
        self.control(word)


def check_load(blocks, first, kernel_forth, kernel_asm, defined_before=()):
    """Follow `first LOAD` through `-->` in `blocks` ({n: 1024 bytes}), after loads
    that defined `defined_before`.  Returns (blocks loaded in order, names defined in
    order, problems)."""
    load = _Load(kernel_forth, kernel_asm)
    load.defined_upper.update(name.upper() for name in defined_before)
    loaded, n = [], first
    while n in blocks:
        loaded.append(n)
        found = words(blocks[n], n)
        following = iter(found)
        for word in following:
            load.step(word, following)
        if not found or found[-1].text != "-->":
            break
        n += 1
    if load.compiling is not None and load.compiling.text == ":":
        load.problem(load.compiling, f"the definition of {load.defined[-1]} never ends")
    if n not in blocks and loaded and n != loaded[-1]:
        load.problems.append(f"block {loaded[-1]} chains with --> to block {n}, which is missing")
    return loaded, load.defined, load.problems
