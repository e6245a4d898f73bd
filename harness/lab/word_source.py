"""Where a FORTH word was defined: the block and line of its definition, found in
the source text of the blocks (pure logic, kernel-independent).

The program pane marks this line when the machine stops at a breakpoint on the
word, or at an I/O breakpoint inside it. The blocks are read as the FORTH reads
them: blank-separated words, `( ... )` and `\\` comments skipped; a definition is
a defining word followed by the name (case ignored, as the kernel's dictionary
search). Of several definitions the last in block order is taken (blocks load in
order: 1000 LOAD chains up, a later definition hides an earlier one). A word
the blocks do not define (the kernel's own: `.`, `EMIT`) has no line.
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


def definition(name, blocks):
    """(block, line) of the last definition of `name` in `blocks`, an iterable of
    (number, its 16 lines), or None."""
    found, wanted = None, name.upper()
    for number, lines in blocks:
        in_comment, previous = False, None
        for line_no, line in enumerate(lines):
            words, in_comment = words_of(line, in_comment)
            for _, word in words:
                if previous in DEFINERS and word.upper() == wanted:
                    found = (number, line_no)
                previous = word.upper()
    return found
