"""The kernel behaviours blocks 1000-1012 rely on (blocks/KERNEL-WORDS.md),
checked on the machine: FORTH-79's state-smart tick, CODE and ;CODE with the
resident assembler, a CODE word ended by the next defining word."""
from harness.machine.robot import numbers


def test_tick_is_state_smart(boot):
    r = boot()
    r.send(": T1 ( -- xt ) ' DUP ;")           # compiles DUP's address as a literal
    assert numbers(r.send("T1 ' DUP = ."))[0] == -1
    assert numbers(r.send("T1 TICK DUP = ."))[0] == -1  # the parsing tick, kept


def test_code_and_semicolon_code(boot):
    r = boot()
    # a CODE word ended by the next colon definition, as in block 1008
    r.send("CODE 3+ ( n -- n+3 ) S ) 3 # ADD, NEXT,")
    r.send(": SIX ( -- 6 ) 3 3+ ;")
    assert r.send("SIX .") == "6 "
    # ;CODE: the children run the code with W = their body
    r.send(": KON ( n \"name\" -- ) CREATE , ;CODE S -) W ) MOV, NEXT, END-CODE")
    r.send("42 KON ANSWER")
    assert r.send("ANSWER .") == "42 "
    # an unbalanced ;CODE body is refused and the defining word discarded
    ok, out, err = r.reply(": BAD CREATE ;CODE MI IF, NEXT, END-CODE")
    assert not ok and "unbalanced structure" in err
    assert not r.reply("' BAD")[0]
    # an error with an operand pending: X1 is discarded, the operand cleared
    # (ASM-RESET in 'ON-ERROR), so the next CODE word assembles cleanly
    ok, out, err = r.reply("CODE X1 R0 NO-SUCH-WORD")
    assert not ok and "undefined word" in err and not r.reply("' X1")[0]
    r.send("CODE 1+! ( a -- ) T S )+ MOV, T ) INC, NEXT, END-CODE")
    assert r.send("VARIABLE V 5 V ! V 1+! V @ .") == "6 "
