"""What each line of the loaded blocks put into memory.

`1000 LOAD` is run on build/pdp11 with a SIMH breakpoint on the kernel's
PARSE-NAME whose actions examine BLK, >IN, HERE (DP), STATE and CONTEXT and
continue: one event each time the interpreter (or a defining word) takes a
name from the source. The words that went into the dictionary between one event
and the next belong to the name taken at the first of them, hence to the block
line where that name stands. A second run of the same command, without the
breakpoint on PARSE-NAME (the machine is deterministic: the same instructions
lay down the same words), dumps those words and has SIMH disassemble the parts that were
assembled: bytes laid down while CONTEXT was ASSEMBLER and STATE was 0 (inside
a CODE word), the machine code. Everything else is headers and threaded code
(addresses of words), annotated with the names of the words they point at.

Machine code reads with names: an operand that is a word's data (an ARRAY's or
VAR's body: `MOV Desire.Pos(R1),R2`), a constant's value (`MOV R0,@#CntOut`) or
a kernel address (kernel.map) is printed as that name, and I/O addresses get the
register's name as a comment. Threaded code is annotated with the names of the
words it calls (a name defined twice, like the editor's T and the assembler's T,
by its address); the words of a header (link, count, name) are not annotated, nor
are a thread's inline cells (a literal, a string, a branch's target: 1024 is
not DOCOL), except a literal that is the xt of a word the blocks define
(' Interrupt.Servo).

Blocks beyond the appendix (1020, 1030-1031) are listed too: `1000 LOAD` runs
first, then each chain of blocks (joined by -->) that the range touches is LOADed
from its first block.

Note what this shows of the 1983 blocks: Stop? and Change.Speed? (1002-1007) are
colon definitions whose bodies are calls to assembler words; the servo's machine
code is laid down by block 1008 line 2, when CODE Interrupt.Servo runs them.
"""
import re
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from harness.machine import simh
from harness.machine.build import KERNEL, KERNEL_MAP, PRISTINE_DISK as PRISTINE, fresh_disk
from harness.machine.kernel_layout import BODY, code_field, map_names, read_kernel_map

BLOCK_BYTES, LINE_CHARS = 1024, 64
# The FORTH's console output shares SIMH's stdout and can land inside an
# examined line ("6252: ok\n\t001764"), so values are found by address, skipping
# anything that is not a tab and a number.
APPENDIX = range(1000, 1013)
IO_NAMES = {0o167770: "DRV11 CSR", 0o167772: "DRV11 OUTBUF", 0o167774: "DRV11 INBUF",
            0o170440: "AAV11 DAC x", 0o170442: "AAV11 DAC y", 0o170444: "AAV11 DAC z",
            0o170446: "AAV11 DAC t", 0o177546: "KW11-L LKS", 0o177560: "DL11 RCSR",
            0o177562: "DL11 RBUF", 0o177564: "DL11 XCSR", 0o177566: "DL11 XBUF"}
INDEXED = re.compile(r"(?<![#\w])([0-7]+)(\((?:R[0-7]|SP|PC)\))")
ABSOLUTE = re.compile(r"@#([0-7]+)")
BREAK = re.compile(r"Breakpoint, PC: ([0-7]+) ")
WORD = re.compile(r"^([0-7]+):\t([0-7]+)$", re.M)
DISASSEMBLED = re.compile(r"^([0-7]+):\t(\S.*)$", re.M)


class ListingError(RuntimeError):
    """The listing could not be made (bad block range, no kernel, load failed)."""


@dataclass
class Event:
    blk: int
    to_in: int
    here: int
    state: int
    context: int


@dataclass
class Span:
    """Dictionary words laid down while one name of the source was handled."""
    start: int
    end: int
    code: bool                     # assembled machine code (CODE word body)
    name: str = ""                 # the source name being handled
    words: list = field(default_factory=list)
    header: str = ""               # the name, when the span begins with its header
    cfa: int = 0                   # its code field (header words end there)
    disassembly: list = field(default_factory=list)   # (address, words, text)


def _symbols(kernel_map):
    return read_kernel_map(kernel_map, ("PARSE-NAME", "BLK", ">IN", "DP", "STATE",
                                        "CONTEXT", "ASSEMBLER"))


def _watched(sym):
    return [sym[n] + BODY for n in ("BLK", ">IN", "DP", "STATE", "CONTEXT")]


def _load_script(sym, disk, kernel, after_load="", watch=True):
    """Boot, type the command, stop at the prompt after it: with `watch`, stopping
    at each PARSE-NAME to examine the watched variables."""
    vals = ";".join(f"ex {a:o}" for a in _watched(sym))
    during = (f"nobreak {sym['QUERY']:o}\nbreak {sym['PARSE-NAME']:o};{vals};cont\n"
              f"break {sym['QUERY']:o}\n" if watch else "")
    return (f"attach rl0 {disk}\nload {kernel}\n"
            f"break {sym['QUERY']:o}\ngo\n{during}cont\nnobreak all\n" + after_load)


def _run(sym, image, kernel, after_load="", command="1000 LOAD", watch=True):
    with tempfile.TemporaryDirectory(prefix="listing-") as tmp:
        disk = fresh_disk(tmp, source=image)   # the image itself is never written
        return simh.run(_load_script(sym, disk, kernel, after_load, watch),
                        keyboard=command + "\r", timeout=120)


def parse_events(output, parse_name, addresses):
    """One Event per stop at PARSE-NAME, with the examined values of `addresses`
    (BLK >IN DP STATE CONTEXT, in that order)."""
    events = []
    stops = list(BREAK.finditer(output))
    for stop, after in zip(stops, stops[1:] + [None]):
        if int(stop.group(1), 8) != parse_name:
            continue
        text = output[stop.end():after.start() if after else len(output)]
        values = [re.search(rf"(?m)^{a:o}:[^\t]*\t([0-7]+)", text) for a in addresses]
        if all(values):
            events.append(Event(*(int(v.group(1), 8) for v in values)))
    return events


def name_at(text, to_in):
    """(start offset, name) of the next blank-delimited name at or after to_in."""
    pos = to_in
    while pos < len(text) and text[pos] == " ":
        pos += 1
    end = text.find(" ", pos)
    end = len(text) if end < 0 else end
    return pos, text[pos:end]


def attribute(events, final_here, assembler_context, block_text):
    """{(block, line): [Span]} for the words laid down while loading."""
    spans = {}
    for k, ev in enumerate(events):
        nxt = events[k + 1] if k + 1 < len(events) else None
        end = nxt.here if nxt else final_here
        if ev.blk == 0 or end <= ev.here:
            continue
        text = block_text(ev.blk)
        pos, name = name_at(text, ev.to_in)
        line = min(pos, BLOCK_BYTES - 1) // LINE_CHARS
        code = (ev.state == 0 and ev.context == assembler_context and nxt is not None
                and nxt.state == 0 and nxt.context == assembler_context)
        spans.setdefault((ev.blk, line), []).append(Span(ev.here, end, code, name))
    return spans


def _header_name(words_by_addr, start, expected):
    """The name if a header (link, count, name) for `expected` starts at `start`."""
    first = words_by_addr.get(start + 2)
    if first is None or not expected:
        return ""
    count = first & 0o377
    if count != len(expected):
        return ""
    raw = bytearray([first >> 8])
    addr = start + 4
    while len(raw) < count:
        w = words_by_addr.get(addr, 0)
        raw += bytes([w & 0o377, w >> 8])
        addr += 2
    return expected if raw[:count].decode("latin-1").upper() == expected.upper() else ""


# words a thread follows with an inline cell (a number, a branch's target, a
# local's offset), or with a counted string (forth/kernel/tools.fs SEE-COLON knows
# the same): those cells are data, not calls, so they name nothing
CELL_OPERAND = ("(LIT)", "BRANCH", "?BRANCH", "(DO)", "(?DO)", "(LOOP)", "(+LOOP)",
                "(LOCAL@)", "(LOCAL!)", "(ENDLOCALS)")
BRANCHES = ("BRANCH", "?BRANCH", "(DO)", "(?DO)", "(LOOP)", "(+LOOP)")
STRING_OPERAND = ('(.")', '(S")', '(ABORT")')
JSR_IP = 0o004437          # a colon definition's code field: JSR R4,@#DOCOL


def thread_operands(words, cfa, sym):
    """{address: "lit" or ""} for the inline operand cells (literals; branch
    targets, offsets, strings) of the colon definition whose code field is at
    `cfa`, following its thread as SEE does: to the EXIT that no branch jumps
    past; a DOES> part (the JSR R4,@#DODOES after (DOES>)) is followed too."""
    if words.get(cfa) != JSR_IP or words.get(cfa + 2) != sym.get("DOCOL"):
        return {}
    xt = {name: sym.get(name) for name in CELL_OPERAND + STRING_OPERAND + ("EXIT", "(DOES>)")}
    cells, branch, string = ({xt[n] for n in names} - {None}
                             for names in (CELL_OPERAND, BRANCHES, STRING_OPERAND))
    operands, a, far = {}, cfa + BODY, cfa
    while a in words:
        w = words[a]
        if w in cells:
            operands[a + 2] = "lit" if w == xt["(LIT)"] else ""
            if w in branch:
                far = max(far, words.get(a + 2, 0))
            a += 4
        elif w in string:
            length = words.get(a + 2, 0) & 0o377            # count byte, then the text
            end = (a + 2 + 1 + length + 1) & ~1
            operands.update(dict.fromkeys(range(a + 2, end, 2), ""))
            a = end
        elif w == xt["(DOES>)"] and words.get(a + 2) == JSR_IP:
            operands.update({a + 2: "", a + 4: ""})           # JSR R4,@#DODOES
            a += 6
        elif w == xt["EXIT"] and a >= far:
            break
        else:
            a += 2
    return operands


def symbolic(text, operands, constants):
    """A SIMH disassembly with operand addresses named: X(Rn) by the data word at X,
    @#A by the constant whose value is A or the data word at A; an I/O register's
    name follows as a comment."""
    notes = []

    def named(m, mode):
        a = int(m.group(1), 8)
        if a in IO_NAMES:
            notes.append(IO_NAMES[a])
        name = (constants.get(a) or operands.get(a)) if mode == "@#" else \
            (operands.get(a) or constants.get(a))
        return (f"@#{name or m.group(1)}" if mode == "@#" else f"{name or m.group(1)}{m.group(2)}")

    text = INDEXED.sub(lambda m: named(m, "X"), text)
    text = ABSOLUTE.sub(lambda m: named(m, "@#"), text)
    return text + (f"  ; {', '.join(notes)}" if notes else "")


def listable_blocks(image_bytes):
    """The non-blank blocks from 1000 on: what a listing can show."""
    count = len(image_bytes) // BLOCK_BYTES
    return [n for n in range(1000, count)
            if image_bytes[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES].strip(b" \0")]


def chain_starts(first, last, block_text):
    """The blocks to LOAD, after 1000 LOAD, so that first..last get loaded: the
    first block of each chain (blocks joined by a final -->) beyond the appendix."""
    def continued(n):
        words = block_text(n).split()
        return bool(words) and words[-1] == "-->"
    starts = []
    for n in range(max(first, APPENDIX.stop), last + 1):
        if not block_text(n).strip(" \0"):
            continue
        start = n
        while start - 1 >= APPENDIX.stop and continued(start - 1):
            start -= 1
        if start not in starts:
            starts.append(start)
    return starts


@dataclass
class Listing:
    blocks: dict                   # block -> 16 lines of text
    spans: dict                    # (block, line) -> [Span]
    names: dict                    # address -> name (kernel words and new words)
    operands: dict = field(default_factory=dict)    # data address -> name
    constants: dict = field(default_factory=dict)   # a CON's value -> its name
    inline: dict = field(default_factory=dict)      # a thread's literal, target, string cells:
                                                    # address -> what to note (a literal's value)

    def format(self):
        out = []
        for blk in sorted(self.blocks):
            out.append(f"Block {blk}")
            for line, text in enumerate(self.blocks[blk]):
                out.append(f"{line:2} {text.rstrip()}")
                out.extend(self.line_code(blk, line))
            out.append("")
        return "\n".join(out)

    def line_code(self, blk, line):
        """The rows of what block `blk`'s line `line` laid down (the lab's program pane)."""
        return [row for span in self.spans.get((blk, line), ()) for row in self._format_span(span)]

    def _format_span(self, span):
        rows = []
        if span.header:
            rows.append(f"     {span.start:06o}  header of {span.header}")
        if span.code and span.disassembly:
            for addr, words, text in span.disassembly:
                octal = " ".join(f"{w:06o}" for w in words)
                text = symbolic(text, self.operands, self.constants)
                rows.append(f"     {addr:06o}  {octal:<21} {text}")
            return rows
        first = span.start & ~1
        for i in range(0, len(span.words), 6):
            chunk = span.words[i:i + 6]
            octal = " ".join(f"{w:06o}" for w in chunk)
            names = [self.inline.get(a, self.names.get(w, "")) if a > span.cfa else ""
                     for a, w in ((first + 2 * (i + k), w) for k, w in enumerate(chunk))]
            # a header's words name nothing; a literal says its value
            note = " ".join(n for n in names if n)
            rows.append(f"     {span.start + 2 * i:06o}  {octal:<41} {note}".rstrip())
        return rows


def make_listing(first=1000, last=1012, image=PRISTINE, kernel=KERNEL, kernel_map=KERNEL_MAP,
                 first_load=()):
    """`1000 LOAD` (the blocks chain with -->), the blocks of `first_load`, the
    chains of any later blocks in the range, and list blocks first..last."""
    for what, path in (("disk image", image), ("kernel", kernel), ("kernel map", kernel_map)):
        if not Path(path).is_file():
            raise ListingError(f"the {what} {path} does not exist (run make)")
    sym = _symbols(kernel_map)
    image_bytes = Path(image).read_bytes()
    present = listable_blocks(image_bytes)
    if first > last or first not in present or last not in present:
        raise ListingError(f"blocks {first}-{last}: {image} holds blocks "
                           f"{format_ranges(present)}")

    def block_text(n):
        return image_bytes[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES].decode("latin-1")

    loads = [1000] + [n for n in first_load if n != 1000]
    loads += [n for n in chain_starts(first, last, block_text) if n not in loads]
    command = " ".join(f"{n} LOAD" for n in loads)
    first_run = _run(sym, image, kernel, f"ex {sym['DP'] + BODY:o}\n", command)
    if "Error:" in first_run:
        message = re.search(r"Error: [^\r\n]*", first_run).group(0)
        raise ListingError(f"{command} failed: {message.strip()} (blocks it needs "
                           "first: --load N)")
    events = parse_events(first_run, sym["PARSE-NAME"], _watched(sym))
    if not events:
        raise ListingError("no events: the breakpoint on PARSE-NAME never fired")
    final_here = int(WORD.findall(first_run)[-1][1], 8)
    start = next(e.here for e in events if e.blk)
    spans = attribute(events, final_here, sym["ASSEMBLER"] + BODY, block_text)

    # the second run dumps memory and disassembles the code spans
    code_spans = [s for ss in spans.values() for s in ss if s.code]
    dump = f"ex {start:o}-{final_here - 2:o}\n" + "".join(
        f"ex -m {s.start:o}-{s.end - 2:o}\n" for s in code_spans)
    second_run = _run(sym, image, kernel, dump, command, watch=False)
    tail = second_run[second_run.rindex(f"Breakpoint, PC: {sym['QUERY']:06o}"):]
    words = {int(a, 8): int(v, 8) for a, v in WORD.findall(tail)
             if start <= int(a, 8) < final_here}
    disassembled = {int(a, 8): t.strip() for a, t in DISASSEMBLED.findall(tail)
                    if not re.fullmatch(r"[0-7]+", t.strip())}

    # only code addresses name a cell: small numbers (0, 1, ...) are data
    names = {a: n for a, n in map_names(kernel_map).items() if a >= sym.get("ORIGIN", 0)}
    operands = {a + BODY: n for a, n in names.items()}     # a kernel variable's body
    operands.update(names)                                 # labels and EQUs as they are
    constants = {}
    for span in (s for ss in spans.values() for s in ss):
        header_at = (span.start + 1) & ~1
        span.header = _header_name(words, header_at, span.name)
        if span.header:             # link, count + name (aligned), then the code field
            span.cfa = code_field(header_at, len(span.name))
            names[span.cfa] = operands[span.cfa + BODY] = span.name
            if words.get(span.cfa + 2) == sym.get("DOCON"):
                constants.setdefault(words.get(span.cfa + BODY), span.name)
    inline = {}
    defined = {s.cfa: s.header for ss in spans.values() for s in ss if s.header}
    for cfa in defined:
        inline.update(thread_operands(words, cfa, sym))
    for a, kind in inline.items():      # a literal names a word only as its xt (' Name);
        if kind == "lit":               # the number itself is in the octal column
            inline[a] = f"' {defined[words[a]]}" if words.get(a) in defined else ""
    for ss in spans.values():
        for span in ss:
            span.words = [words.get(a, 0) for a in range(span.start & ~1, span.end, 2)]
            if span.code:
                addrs = sorted(a for a in disassembled if span.start <= a < span.end)
                for a, b in zip(addrs, addrs[1:] + [span.end]):
                    span.disassembly.append(
                        (a, [words.get(x, 0) for x in range(a, b, 2)], disassembled[a]))
    blocks = {n: [block_text(n)[i:i + LINE_CHARS] for i in range(0, BLOCK_BYTES, LINE_CHARS)]
              for n in range(first, last + 1) if n in present}
    spans = {k: v for k, v in spans.items() if first <= k[0] <= last}
    return Listing(blocks, spans, names, operands, constants, inline)


def format_ranges(numbers):
    """[1000, 1001, 1002, 1020] -> "1000-1002, 1020"."""
    runs = []
    for n in numbers:
        if runs and n == runs[-1][1] + 1:
            runs[-1][1] = n
        else:
            runs.append([n, n])
    return ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs) or "none"
