"""Pastes of FORTH definitions, as a student pastes a block or a source file:
each line defines a word and runs it at once, adding its number to a total, so
a single lost or garbled character shows as an error or a wrong total at the end
(issue 23's measure)."""

PAD = "( pasted )"


def definitions(chars):
    """(text, n): a VARIABLE, then n definitions P1..Pn in about `chars`
    characters, lines of about 60 characters each ending in CR."""
    lines = ["VARIABLE PASTED  0 PASTED !\r"]
    total, k = len(lines[0]), 0
    while total < chars:
        k += 1
        line = f": P{k} {PAD} {k} ;  P{k} PASTED +!  \\ definition {k}\r"
        lines.append(line)
        total += len(line)
    return "".join(lines), k


def check_line():
    """A line whose answer is the total: n(n+1)/2 when all n arrived whole."""
    return "PASTED @ U."


def expected(n):
    return n * (n + 1) // 2 % 65536
