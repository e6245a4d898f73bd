"""Every error class: a clear message naming the word, then the interpreter
works again with the stacks reset and the dictionary intact."""
import pytest


def still_works(forth):
    assert forth.send("DEPTH .") == "0 "
    assert forth.send("2 3 + .") == "5 "


@pytest.mark.parametrize("line, message, word", [
    ("NO-SUCH-WORD", "undefined word", "NO-SUCH-WORD"),
    ("DROP", "stack underflow", "DROP"),
    ("THEN", "compile-only word interpreted", "THEN"),
    ("1 >R", "compile-only word interpreted", ">R"),
    (": BAD IF ;", "unbalanced control structure", ";"),
    (": BAD2 BEGIN THEN ;", "unbalanced control structure", "THEN"),
    ("1 @", "odd address for a word access", "@"),
    ("160000O @", "bus error or odd address (vector 000004, PC", "@"),
    ("5 0 /", "division by zero", "/"),
    (": RUNAWAY RECURSE ; RUNAWAY", "return stack overflow", "RUNAWAY"),
    ("HERE 10O , EXECUTE", "not an execution token", "EXECUTE"),   # issue 16: checked
    ("HERE 100 + EXECUTE", "not an execution token", "EXECUTE"),
    ("0 EXECUTE", "not an execution token", "EXECUTE"),
    ("30000 ALLOT 30000 ALLOT", "dictionary full", "ALLOT"),
    ("-30000 ALLOT -30000 ALLOT", "invalid memory address", "ALLOT"),
    ("10240 BLOCK", "no such block", "BLOCK"),
])
def test_error_then_prompt(forth, line, message, word):
    r = forth.reply(line)
    assert not r.ok, r
    assert message in r.error
    assert r.error.endswith(": " + word)
    still_works(forth)


def test_stack_overflow(forth):
    for _ in range(10):  # 50 numbers a line; the stack holds about 240
        r = forth.reply(" ".join(["7"] * 50))
        if not r.ok:
            break
    assert r.error == "stack overflow: 7"
    still_works(forth)


def test_runaway_push_loop(forth):
    assert forth.reply("BEGIN 1 AGAIN").error == "stack overflow: AGAIN"
    still_works(forth)
    assert forth.reply(": PUSHES 30000 0 DO I LOOP ; PUSHES").error == "stack overflow: PUSHES"
    still_works(forth)


def test_interrupted_definition_leaves_nothing(forth):
    before = forth.send("HERE .")
    assert not forth.reply(": HALF-DONE 1 2 NOWHERE").ok
    assert forth.send("HERE .") == before
    assert "undefined word" in forth.reply("HALF-DONE").error
    still_works(forth)


def test_typed_control_structure_cut_short(forth):
    before = forth.send("HERE .")
    assert forth.reply("3 0 DO I . NOWHERE").error == "undefined word: NOWHERE"
    assert forth.send("HERE .") == before
    still_works(forth)


def test_abort_quote_message(forth):
    forth.send(': CHECK ( n -- ) 0< ABORT" negative input" ;')
    r = forth.reply("-3 CHECK")
    assert r.error == "negative input: CHECK"
    still_works(forth)


def test_control_c_stops_a_runaway_loop(forth):
    forth.child.send("BEGIN AGAIN\r")
    forth.child.expect("BEGIN AGAIN ")  # echoed: the loop is running
    forth.child.sendcontrol("c")
    forth.child.expect(r"\r\nError: interrupted by \^C: AGAIN\r\n")
    still_works(forth)


def test_trapping_interrupt_handler_is_taken_out(forth):
    """A clock handler that traps (bus error) is reported once, and its vector
    goes back to the default handler instead of trapping at every tick."""
    from harness.machine.machine import ERROR
    forth.send("CODE BADINT 160000O @# TST, RTI, END-CODE")
    forth.send(": LKS-ON 100O 177546O ! ;  : CLOCK-ON ['] LKS-ON CATCH DROP ;")
    forth.send("CLOCK-ON")  # the stock clock is always on
    forth.child.send("' BADINT 100O !\r")
    forth.child.expect(ERROR)
    assert "in BADINT; vector 000100 restored to its default handler" in \
        forth.child.match.group(1)
    assert forth.send("100O @ 1100O = .").endswith("-1 ")
    still_works(forth)


def test_caught_trap_leaves_interrupts_on(forth):
    """A trap caught by CATCH (probing a register that may not exist) still
    lowers the priority: the console keeps working."""
    assert forth.send("' 160000O CATCH . 177776O @ 340O AND .".replace("' 160000O", ": PROBE 160000O @ ; ' PROBE")) == "-256 0 "
    still_works(forth)
