"""Random console lines of the kinds a student types (issue 8), seeded.

    maker = LineMaker(seed=1)
    maker.line()        # e.g. ": F3 2 0 DO I NOSUCH LOOP" or "5 1 BASE ! ."

Kinds: undefined words, bad numbers, unbalanced control structures, stack
abuse, BASE outside 2..36, CATCH/THROW misuse, reversed block ranges and
blocks off the disk; issue 16's: the return stack misused (>R R> R@ 2>R 2R> in
and out of loops), control structures at the prompt that lay down with , and
ALLOT, REFILL (the next line is what it reads); never a raw memory store (no ! C! FILL MOVE SP! RP! TO,
no EXECUTE or CATCH of a number: those two come only after a line that empties
the stack), no kernel word redefined (a defining or parsing word always takes a
name never used before, so compiled into a definition it is an error, not a word
that parses the caller's next word when it runs), never a line that would
rightly run for ever. What ends every loop: DO takes two small literals (n 0 DO), +LOOP a
literal positive step, UNTIL a literal 1 and WHILE a literal 0 just before it,
REPEAT and AGAIN close only those; UNLOOP comes only as UNLOOP EXIT; a
definition calls earlier ones only outside its loops. Control-flow tags keep
any other pairing from compiling.
"""
import random

UNDEFINED = ["NOSUCH", "Abs.Mov", "Set.Up", "FOOBAR", "xyzzy", "DUPE", "SWAPP", "qwe", "Z9"]
BAD_NUMBERS = ["12x4", "--5", "0x1F", "1.5", "$FF", "1-2", "12O9", "O", "1,2", "99999999",
               "--", "7O7O", "-O", "3e4"]
STACK = ["DUP", "DROP", "SWAP", "OVER", "ROT", "NIP", "TUCK", "2DUP", "2DROP", "2SWAP",
         "2OVER", "?DUP", "PICK", "ROLL", "DEPTH", "+", "-", "*", "/", "MOD", "/MOD",
         "NEGATE", "ABS", "MIN", "MAX", "=", "<", ">", "0=", "AND", "OR", "XOR", "INVERT",
         "1+", "1-", "2*", "2/", "LSHIFT", "RSHIFT", "*/", "M*", "UM*", "UM/MOD", "SM/REM",
         "FM/MOD", "S>D", "D+", "DNEGATE", "WITHIN", "CELLS"]
PRINT = [".", "U.", ".S", "D.", "5 .R", "?", "DEPTH ."]
BODY_ONLY = ["I", "J", "LEAVE", "EXIT", "UNLOOP EXIT", "RECURSE", "IF", "ELSE", "THEN",
             "BEGIN", "LOOP", "1 +LOOP", "2 +LOOP", "[", "]", "LITERAL", "POSTPONE DUP",
             "[']", "' DUP", "['] DROP"]
OPEN_DO = ["2 0 DO", "3 0 DO", "4 1 ?DO", "1 1 ?DO"]
CATCHABLE = ["DUP", "DROP", "NOSUCH", ".", "THROW", "ABORT", "DEPTH", "2DROP"]
EMPTIES_STACK = "EMPTY-THE-STACK"     # never defined: its error empties the stacks
# the return stack misused inside a definition that runs at once: each leaves
# EXIT a small number, its own caller's return or a loop running away; an EXIT
# to an arbitrary stack value (a bare >R) can land inside the kernel, which the
# kernel does not claim to catch (forth/README.md, What protects you): typed only
RETURN_STACK = ["5 >R R> .", "1 2 2>R 2R> + .", "7 >R R@ . R> DROP", "1 >R", "40 >R",
                "R>", "R> DROP", "2R>", "R@ .", "1 2 2>R", "3 0 DO I >R LOOP",
                "3 0 DO R> DROP LOOP", "2 0 DO I >R R> . LOOP", "4 0 DO 1 >R LOOP",
                "2 0 DO 1 2 2>R 2R> 2DROP LOOP", "0 >R EXIT", "-1 >R", "3 >R 2 >R"]
RETURN_STACK_TYPED = [">R", "I >R", "R>", "2>R", "R@", "2R>", "1 >R R>"]
LAYS_DOWN = ["3 0 DO I , LOOP", "2 0 DO 4 ALLOT LOOP", "1 IF 7 , THEN", "4 0 DO I C, LOOP ALIGN",
             "0 IF 9 , ELSE 8 , THEN", "BEGIN 5 , 1 UNTIL", "2 0 DO HERE , 2 ALLOT LOOP", "-4 ALLOT"]
REFILLS = ["REFILL DROP", "REFILL . SOURCE TYPE", "1 2 REFILL DROP .S",
           "-1 [IF] 2 [ELSE] 3 [THEN] 4 REFILL DROP", "0 [IF] 5 [ELSE] 6 REFILL [THEN] . ."]
THROW_CODES = [0, 1, 5, -1, -2, -3, -4, -5, -13, -22, -28, -256, 32767, -32768]
WORDS_WITH_NAMES = ["VARIABLE", "CONSTANT", "CREATE", "VALUE", ":", "FORGET", "MARKER", "'",
                    "POSTPONE", "CHAR", "[CHAR]", "SEE"]


class LineMaker:
    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.defined = 0              # F0 .. F<defined-1> have been named
        self.pending = []             # lines that must follow the last one
        self.names = 0                # N0 N1 ...: each name a defining word takes is new

    # ---- pieces ---------------------------------------------------------------------
    def number(self):
        r = self.rng
        return r.choice([str(r.randint(-3, 20)), str(r.randint(-32768, 65535)), "177O",
                         "-1", "0", "40000", "100000O"])

    def undefined(self):
        r = self.rng
        return r.choice(UNDEFINED) + (str(r.randint(0, 99)) if r.random() < 0.5 else "")

    def earlier_word(self):
        return f"F{self.rng.randrange(self.defined)}" if self.defined else "DUP"

    def simple(self):
        """A token that never branches back."""
        r = self.rng
        kind = r.random()
        if kind < 0.30:
            return self.number()
        if kind < 0.55:
            return r.choice(STACK)
        if kind < 0.65:
            return r.choice(PRINT)
        if kind < 0.75:
            return r.choice(BAD_NUMBERS)
        if kind < 0.85:
            return self.undefined()
        if kind < 0.92:
            # a new name: in a definition it is undefined, so a defining or parsing
            # word is never compiled to parse (and redefine .) when the word runs
            self.names += 1
            return f"{r.choice(WORDS_WITH_NAMES)} N{self.names}"
        return r.choice(["HEX", "DECIMAL", "OCTAL", "BASE @ .", "HERE .", "BL", "TRUE", "FALSE"])

    def loop_template(self, depth):
        r = self.rng
        inner = self.body(depth + 1, r.randint(0, 4))
        return r.choice([f"BEGIN {inner} 1 UNTIL",
                         f"BEGIN {inner} 0 WHILE {self.body(depth + 1, 2)} REPEAT",
                         f"BEGIN {inner} 0 WHILE {self.body(depth + 1, 2)} AGAIN",
                         f"{r.randint(1, 4)} 0 DO {inner} LOOP",
                         f"{r.randint(1, 4)} 0 ?DO {inner} {r.randint(1, 2)} +LOOP",
                         f"1 IF {inner} ELSE {self.body(depth + 1, 1)} THEN"])

    def body(self, depth, length, calls=True):
        """Tokens for a definition or a structure typed at the prompt; `depth`
        counts the loops around it (no call of an earlier word inside one)."""
        r, out = self.rng, []
        for _ in range(length):
            kind = r.random()
            if kind < 0.50:
                out.append(self.simple())
            elif kind < 0.72:
                out.append(r.choice(BODY_ONLY))
            elif kind < 0.76:
                out.append(r.choice(OPEN_DO))       # maybe never closed: no calls after it
                depth += 1
            elif kind < 0.88 and depth < 3:
                out.append(self.loop_template(depth))
            elif depth == 0 and calls:
                out.append(self.earlier_word())
        return " ".join(out)

    # ---- lines ----------------------------------------------------------------------
    def definition(self):
        name = f"F{self.defined}"
        self.defined += 1
        end = self.rng.choice([" ;", " ;", " ;", "", " ; ;"])
        return f": {name} {self.body(0, self.rng.randint(1, 8))}{end}"

    def issue16(self):
        """The return stack misused, in a definition run at once or typed; a
        structure at the prompt laying down data after CREATE; REFILL."""
        r = self.rng
        kind = r.random()
        if kind < 0.45:
            name = f"F{self.defined}"
            self.defined += 1
            return f": {name} {r.choice(RETURN_STACK)} ; {name}"
        if kind < 0.60:
            return r.choice(RETURN_STACK + RETURN_STACK_TYPED)
        if kind < 0.85:
            self.names += 1
            return f"CREATE N{self.names} {r.choice(LAYS_DOWN)} N{self.names} @ ."
        return r.choice(REFILLS)

    def line(self):
        if self.pending:
            return self.pending.pop(0)
        r = self.rng
        kind = r.random()
        if kind < 0.20:
            text = self.definition()
        elif kind < 0.35:
            text = " ".join(self.simple() for _ in range(r.randint(1, 8)))
        elif kind < 0.45:
            text = self.body(0, r.randint(1, 6))                   # structures typed
        elif kind < 0.55:
            text = f"{r.randint(-3, 40)} BASE ! " + " ".join(self.simple() for _ in range(3))
        elif kind < 0.65:
            text = r.choice([f"' {r.choice(CATCHABLE)} CATCH", "THROW", EMPTIES_STACK,
                             f"{r.choice(THROW_CODES)} THROW", "' THROW CATCH .",
                             f"{r.choice(THROW_CODES)} ' THROW CATCH .", "12345 EXECUTE",
                             f"' {self.earlier_word()} CATCH ."])
            if text == EMPTIES_STACK:
                self.pending.append(r.choice(["CATCH", "EXECUTE", "CATCH CATCH", "THROW"]))
        elif kind < 0.72:
            a, b = sorted(r.sample(range(1, 10300), 2))
            # DECIMAL: in another BASE the digits could wrap round to a long range
            text = "DECIMAL " + r.choice([f"{b} {a} THRU", f"{b} {a} INDEX", f"{b} LIST",
                                          f"{r.choice([0, -1, 10240, 20000])} LOAD",
                                          f"{r.randint(5000, 5100)} DUP 1+ THRU"])
        elif kind < 0.80:
            text = " ".join(str(r.randint(0, 9)) for _ in range(r.randint(20, 80)))
        elif kind < 0.85:
            text = r.choice(["1 2 3 10 ROLL", "1 2 3 10 PICK", "PICK", "ROLL", "-1 PICK",
                             "<# 100 0 DO 65 HOLD LOOP", "<# #S #>", "0 0 <# #S #> TYPE"])
        elif kind < 0.90:
            text = self.body(0, r.randint(1, 4)) + " " + r.choice(["THEN", "LOOP", ";", "ELSE"])
        elif kind < 0.92:
            text = " ".join(self.undefined() for _ in range(r.randint(1, 4)))
        elif kind < 0.97:
            text = self.issue16()
        else:
            text = f'S" {self.body(0, 3, calls=False)}" EVALUATE'
        return text[:200]
