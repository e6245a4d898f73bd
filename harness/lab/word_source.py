"""Where a FORTH word was defined: the block and line of its definition, found in
the source text of the blocks (pure logic, kernel-independent).

The program pane marks this line when the machine stops at a breakpoint on the
word, or at an I/O breakpoint inside it. The blocks are read as the FORTH reads
them: blank-separated words, `( ... )` and `\\` comments skipped; a definition is
a defining word followed by the name (case ignored, as the kernel's dictionary
search). Of several definitions, the one whose neighbours in the source match the
word's neighbours in the dictionary (what was loaded just before and after it).
A word the blocks do not define (the kernel's own: `.`, `EMIT`) has no line.
"""
DEFINERS = {":", "CODE", "VAR", "CON", "ARRAY", "VARIABLE", "CONSTANT", "CREATE",
            "2VARIABLE", "2CONSTANT", "VALUE", "DEFER", "SUBROUTINE", "LABEL"}


def words_of(line, in_comment=False):
    """The words of one line outside comments, and whether a `(` comment is still
    open at its end: ([(column, word)], in_comment)."""
    words, column = [], 0
    for word in line.split(" "):
        start, column = column, column + len(word) + 1
        if not word:
            continue
        if in_comment:
            in_comment = not word.endswith(")")
        elif word == "(":
            in_comment = True
        elif word == "\\":
            break
        else:
            words.append((start, word))
    return words, in_comment


def definitions(blocks):
    """[(NAME, block, line)] of every definition in `blocks`, an iterable of
    (number, its 16 lines), in block order."""
    found = []
    for number, lines in blocks:
        in_comment, previous = False, None
        for line_no, line in enumerate(lines):
            words, in_comment = words_of(line, in_comment)
            for _, word in words:
                if previous in DEFINERS:
                    found.append((word.upper(), number, line_no))
                previous = word.upper()
    return found


def definition(name, blocks, before=(), after=()):
    """(block, line) of the definition of `name` in `blocks`, or None. When several
    blocks define it (block 1031's Interrupt.Servo beside block 1008's), the one
    whose neighbours in the source are the word's neighbours in the dictionary
    (`before`: the names defined just before it, nearest first; `after`: just
    after) is taken; of equals, the last in block order."""
    return definition_among(name, definitions(blocks), before, after)


def definition_among(name, found, before=(), after=()):
    """definition() among `found`, what definitions() gave for the blocks: for a
    caller that looks up many words in the same blocks, which are read once."""
    names = [n for n, _, _ in found]
    best, best_score = None, -1
    for i, (defined, block, line) in enumerate(found):
        if defined != name.upper():
            continue
        score = sum(a.upper() == b for a, b in zip(before, reversed(names[max(0, i - len(before)):i])))
        score += sum(a.upper() == b for a, b in zip(after, names[i + 1:i + 1 + len(after)]))
        if score >= best_score:
            best, best_score = (block, line), score
    return best
