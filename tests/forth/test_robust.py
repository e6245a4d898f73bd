"""Nothing typed at the prompt halts or hangs the machine (issue 8): each case
ends in a FORTH error naming what and which word, then the prompt, with the
stacks reset and the dictionary intact."""
import pytest

from harness.machine.machine import ERROR


def still_works(forth):
    assert forth.send("DEPTH .") == "0 "
    assert forth.send("2 3 + .") == "5 "
    assert forth.send("SQUARE-OF-7 .") == "49 "      # defined before: dictionary intact


@pytest.fixture(scope="module", autouse=True)
def a_word_defined_first(forth):
    forth.send(": SQUARE-OF-7 7 DUP * ;")


@pytest.mark.parametrize("line, message, word", [
    ("5 1 BASE ! .", "BASE outside 2..36 (now DECIMAL)", "."),
    ("0 BASE ! 10", "BASE outside 2..36 (now DECIMAL)", "10"),
    ("37 BASE ! 5 .", "BASE outside 2..36 (now DECIMAL)", "5"),
    ("CATCH", "stack underflow", "CATCH"),
    ("EXECUTE", "stack underflow", "EXECUTE"),
    ("12345 EXECUTE", "odd address for a word access", "EXECUTE"),
    ("1 2 3 3 ROLL", "stack underflow", "ROLL"),
    ("1 2 3 -1 ROLL", "stack underflow", "ROLL"),
    ("1 2 3 3 PICK", "stack underflow", "PICK"),
    ("1 2 3 30000 PICK", "stack underflow", "PICK"),
    ("1005 1003 THRU", "first block after the last", "THRU"),
    ("1005 1003 INDEX", "first block after the last", "INDEX"),
    ("20000 LOAD", "no such block", "LOAD"),
    ("0 LOAD", "block 0 cannot be loaded", "LOAD"),
    ("<# 100 0 DO 42 HOLD LOOP", "pictured numeric output too long", "LOOP"),
    ("HERE HLD ! 65 HOLD", "pictured numeric output too long", "HOLD"),
    (": Y 2 0 DO EXIT LOOP ;", "EXIT inside DO ... LOOP needs UNLOOP first", "EXIT"),
    ("2 0 DO EXIT LOOP", "EXIT inside DO ... LOOP needs UNLOOP first", "EXIT"),
    (": Z LEAVE ;", "LEAVE or UNLOOP outside DO ... LOOP", "LEAVE"),
    (": Z UNLOOP ;", "LEAVE or UNLOOP outside DO ... LOOP", "UNLOOP"),
    ("-256 THROW", "error -256", "THROW"),
    ("RP0 RP!", "return stack underflow", "RP!"),       # EXIT finds RP0's guard
    ("0 RP!", "invalid memory address", "RP!"),
    ("177776O RP!", "invalid memory address", "RP!"),
    ("157000O RP!", "invalid memory address", "RP!"),   # under DOCOL's margin
    ("1 RP!", "odd address for a word access", "RP!"),
    ("0 SP!", "invalid memory address", "SP!"),
    ("S0 2 + SP!", "invalid memory address", "SP!"),
])
def test_error_then_prompt(forth, line, message, word):
    here, rp = forth.send("HERE . RP@ .").split()
    r = forth.reply(line)
    assert r.error == f"{message}: {word}", r
    assert forth.send("BASE @ .") == "10 "
    assert forth.send("HERE . RP@ .").split() == [here, rp]   # both stacks reset
    still_works(forth)


def test_valid_uses_still_work(forth):
    assert forth.send("1 2 3 2 ROLL . . .") == "1 3 2 "
    assert forth.send("1 2 3 0 ROLL . . .") == "3 2 1 "
    assert forth.send("1 2 3 2 PICK . . . .") == "1 3 2 1 "
    assert forth.send(": Y2 2 0 DO 3 0 DO I J + 2 = IF I UNLOOP UNLOOP EXIT THEN LOOP LOOP ; Y2 .") \
        == "2 "
    assert forth.send("2 BASE ! 101 . DECIMAL 36 BASE ! Z . DECIMAL") == "101 Z "
    assert forth.send("-1 -1 2 BASE ! D. DECIMAL") == "-1 "
    assert forth.send("65535 0 2 BASE ! D. DECIMAL") == "1" * 16 + " "
    assert forth.send("' SQUARE-OF-7 CATCH . .") == "0 49 "


def test_empty_stack_prints_no_number(forth):
    for word in (".", "U.", "? ", "5 .R", "D."):
        r = forth.reply(word)
        assert r.error == f"stack underflow: {word.split()[-1]}"
        assert r.output == ""                          # nothing printed before it
    still_works(forth)


def test_user_throw_256_after_a_caught_trap_is_not_a_trap(forth):
    assert forth.send(": PROBE 160000O @ ; ' PROBE CATCH .") == "-256 "
    assert forth.reply("-256 THROW").error == "error -256: THROW"
    still_works(forth)


def test_trap_above_here_names_no_word(forth):
    # a thread run in free space (EXIT's range check lets it pass): its cells,
    # 000040, are xts of address 40, which holds a reserved instruction
    r = forth.reply(": JA [ HERE 100 + ] LITERAL >R ; JA")
    assert r.error.startswith("illegal or reserved instruction (vector 000010, PC 000042")
    assert " in " not in r.error                       # not blamed on the newest word
    still_works(forth)


def test_typed_structure_with_long_output_runs_intact(forth):
    before = forth.send("HERE .")
    line = "3 0 DO " + " ".join(f"I {k} * ." for k in range(1, 12)) + " LOOP"
    assert forth.send(line).split() == [str(i * k) for i in range(3) for k in range(1, 12)]
    assert forth.send("HERE .") == before
    still_works(forth)


def test_open_structure_prompts_compiled(forth):
    forth.child.send("1 IF 7 .\r")
    forth.child.expect(r" compiled\r\n")
    assert forth.send("THEN") == "7 "
    forth.child.send(": HALF 1 2\r")
    forth.child.expect(r" compiled\r\n")
    assert forth.send("; HALF . .") == "2 1 "
    forth.child.send("2 0 DO I .\r")
    forth.child.expect(r" compiled\r\n")
    assert forth.send("LOOP") == "0 1 "
    still_works(forth)


def test_wild_return_stack_in_a_definition(forth):
    assert forth.reply(": WILD 10 RP! ; WILD").error == "invalid memory address: WILD"
    still_works(forth)


def test_control_c_at_idle_prompt_blames_no_word(forth):
    forth.send("1 DROP")
    forth.child.sendcontrol("c")
    forth.child.expect(ERROR)
    assert forth.child.match.group(1) == "interrupted by ^C"
    still_works(forth)


def test_words_created_inside_a_definition_cut_short_leave_with_it(forth):
    """[ CREATE X ] inside a definition or a typed structure that then fails: X
    leaves too, so no chain keeps a header above HERE for the next one to
    overwrite (a header of the same chain as U. once cut U. off)."""
    for line in (": CUT1 [ CREATE INNER1 ] NOSUCH", "1 IF [ CREATE INNER2 ] NOSUCH"):
        assert forth.reply(line).error == "undefined word: NOSUCH"
    for gone in ("INNER1", "INNER2", "CUT1"):
        assert forth.reply(gone).error == f"undefined word: {gone}"
    assert forth.send(": CUT2 ; : LONGER-NAME-4 U. ; 5 LONGER-NAME-4") == "5 "
    still_works(forth)


def test_recurse_never_calls_a_definition_cut_short(forth):
    assert forth.reply(": CUT3 1 2 NOSUCH").error == "undefined word: NOSUCH"
    assert forth.reply("1 IF RECURSE THEN").error == "compile-only word interpreted: RECURSE"
    still_works(forth)
