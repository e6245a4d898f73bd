"""Issue 16: a mistake never costs the dictionary or the disk. Each case is one
of the issue's numbered defects, typed as a FORTH student would: it ends in a
FORTH error naming the word, back at the prompt, with the dictionary, the heap
and the UPDATEd blocks intact (and on the disk after FLUSH), or, for the
language defects, in gforth's answer."""
import pytest

from harness.machine.build import fresh_disk
from harness.machine.machine import Machine

BLOCK = 1024


def block_on_disk(image, n):
    with open(image, "rb") as f:
        f.seek(BLOCK * n)
        return f.read(BLOCK)


@pytest.fixture
def robot_disk(tmp_path):
    """A copy of the robot's disk: blocks 1000-1012 as printed in the paper."""
    return fresh_disk(tmp_path)


def with_work_at_risk(m):
    """Block 300 UPDATEd with Z's, a heap cell and a word: what must survive."""
    m.send("300 BLOCK 1024 90 FILL UPDATE")
    m.send("100 ALLOCATE DROP CONSTANT hp 12345 hp !")
    m.send(": SQUARE-OF-7 7 DUP * ;")


def work_survived(m, image):
    assert m.send("DEPTH . hp @ . SQUARE-OF-7 .") == "0 12345 49 "
    assert m.send("300 BLOCK C@ .") == "90 "
    m.send("FLUSH")
    m.close()
    assert block_on_disk(image, 300) == b"Z" * BLOCK


# ---- 1, 2: the return stack misused ------------------------------------------
@pytest.mark.parametrize("line, message, word", [
    (": r4 10 0 DO I >R LOOP ; r4", "return stack overflow", "r4"),     # 1
    (": deep 1000 0 DO 1 >R LOOP ; deep", "return stack overflow", "deep"),  # 2
    (": t1 1 >R ; t1", "return stack unbalanced (EXIT into data)", "t1"),
    (": t2 R> R> R> R> R> ; t2", "return stack underflow", "t2"),
])
def test_return_stack_misuse_is_an_error_and_loses_nothing(robot_disk, line, message, word):
    m = Machine(disk=robot_disk)
    try:
        with_work_at_risk(m)
        assert m.reply(line).error == f"{message}: {word}"
        work_survived(m, robot_disk)
    finally:
        m.close()


def test_return_stack_overflow_after_the_blocks_load(robot_disk):
    m = Machine(disk=robot_disk, timeout=60)
    try:
        with_work_at_risk(m)
        m.send("1000 LOAD")                                        # 1: r5
        assert m.reply(": r5 20 0 DO I 7 * >R LOOP ; r5").error == "return stack overflow: r5"
        work_survived(m, robot_disk)
    finally:
        m.close()


# ---- nothing the program did not write reaches the disk ------------------------
def test_a_buffer_a_wild_run_changed_is_not_saved(robot_disk):
    m = Machine(disk=robot_disk)
    try:
        before = block_on_disk(robot_disk, 300)
        m.send("300 BLOCK 1024 90 FILL UPDATE  301 BLOCK 1024 65 FILL UPDATE  302 BLOCK DROP")
        # a store into block 300's buffer the program never meant, then a trap
        r = m.reply(": WILD 0 [ 300 BLOCK ] LITERAL ! 160000O @ ; WILD")
        assert r.error.startswith("bus error")
        assert "NOT SAVED: block 300 (changed since its last UPDATE" in r.output
        assert "block 301" not in r.output
        m.send("FLUSH")
        m.close()
        assert block_on_disk(robot_disk, 300) == before          # as it was
        assert block_on_disk(robot_disk, 301) == b"A" * BLOCK    # intact: written
    finally:
        m.close()


def test_writes_before_update_and_in_blocks_window_are_kept(robot_disk):
    m = Machine(disk=robot_disk)
    try:
        m.send("300 BLOCK DROP UPDATE  300 BLOCK 1024 66 FILL UPDATE")
        r = m.reply(": BAD 160000O @ ; BAD")
        assert r.error.startswith("bus error") and "NOT SAVED" not in r.output
        m.send("FLUSH")
        m.close()
        assert block_on_disk(robot_disk, 300) == b"B" * BLOCK
    finally:
        m.close()


# ---- 3: data stack underflow, anywhere --------------------------------------------
@pytest.fixture(scope="module")
def forth():
    with Machine() as m:
        m.send(": SQUARE-OF-7 7 DUP * ;")
        yield m


def still_works(forth):
    assert forth.send("DEPTH .") == "0 "
    assert forth.send("SQUARE-OF-7 .") == "49 "


@pytest.mark.parametrize("line, word", [
    ("SWAP .S", "SWAP"), ("2ROT .S", "2ROT"), ("1 2 */ .S", "*/"), ("DUP .S", "DUP"),
    ("DROP .S", "DROP"), (": under SWAP ; under", "under"), ("1 OVER", "OVER"),
    ("' DROP CATCH .S", None),
])
def test_stack_underflow_names_the_word(forth, line, word):
    r = forth.reply(line)
    if word is None:                      # caught: CATCH gives -4, the frame intact
        assert r.ok and r.output == "<1> -4 "
        forth.send("DROP")
    else:
        assert r.error == f"stack underflow: {word}"
        assert r.output == ""
    assert forth.send("HANDLER @ .") == "0 "
    still_works(forth)


@pytest.mark.parametrize("setup, line, answer", [
    (": peek 160000O @ ;", "7 8 ' peek CATCH . . .", "-256 8 7 "),   # a bus error
    (": deeper 1 2 3 160000O @ ;", "9 ' deeper CATCH . .", "-256 9 "),
    (": under1 SWAP ;", "3 ' under1 CATCH . .", "-4 3 "),           # the MMU abort
])
def test_a_caught_trap_leaves_the_cells_under_the_catch_frame(forth, setup, line, answer):
    """The trap handler pushed its code at S0, over the bottom cells of the data
    stack that CATCH gives back (found by the 11/03's link words, issue 21)."""
    forth.send(setup)
    assert forth.send(line) == answer
    still_works(forth)


# ---- 10, 11: EXECUTE of data, stores into the kernel's vectors -----------------------
@pytest.mark.parametrize("line, message, word", [
    ("VARIABLE v  v EXECUTE", "not an execution token", "EXECUTE"),
    ("1234 EXECUTE", "not an execution token", "EXECUTE"),
    ("CREATE jm 95 , 1234 ,  jm EXECUTE", "not an execution token", "EXECUTE"),
    ("0 4 !", "protected address (the kernel's trap and console vectors)", "!"),
    ("0 48 !", "protected address (the kernel's trap and console vectors)", "!"),
    ("0 48 C!", "protected address (the kernel's trap and console vectors)", "C!"),
    ("0 250O !", "protected address (the kernel's trap and console vectors)", "!"),
    ("1 1000O +!", "protected address (the kernel's trap and console vectors)", "+!"),
    ("0 2000O 0 FILL", "protected address (the kernel's trap and console vectors)", "FILL"),
    ("HERE 40 64 CMOVE", "protected address (the kernel's trap and console vectors)", "CMOVE"),
    ("-2 4 0 FILL", "protected address (the kernel's trap and console vectors)", "FILL"),
])
def test_data_is_not_run_and_kernel_vectors_not_written(forth, line, message, word):
    assert forth.reply(line).error == f"{message}: {word}"
    assert forth.reply("57344 @").error.startswith("bus error")   # vector 4 intact
    assert forth.send("1 2 + .") == "3 "                            # console intact
    still_works(forth)


def test_execute_still_runs_every_kind_of_word(forth):
    forth.send(": ex-c 3 ; VARIABLE ex-v CREATE ex-d 5 , 7 CONSTANT ex-k")
    forth.send(": ex-does CREATE , DOES> @ 1+ ; 41 ex-does ex-dd  SYNONYM ex-syn ex-c")
    assert forth.send("' ex-c EXECUTE . ' ex-k EXECUTE . ' ex-dd EXECUTE . ' ex-syn EXECUTE .") \
        == "3 7 42 3 "
    assert forth.send("' ex-v EXECUTE ex-v = . ' DUP 5 SWAP EXECUTE . . :NONAME 9 ; EXECUTE .") \
        == "-1 5 5 9 "
    assert forth.send("100O @ 100O ! 2 3 ' + EXECUTE .") == "5 "    # 100 up: a program's


# ---- 4: control structures at the prompt lay down , and ALLOT where typed ----------
def test_typed_loop_commas_into_the_word_being_built(forth):
    forth.send("CREATE tbl 3 0 DO I , LOOP")
    assert forth.send("tbl @ . tbl 2 + @ . tbl 4 + @ . HERE tbl - .") == "0 1 2 6 "
    forth.send("CREATE t2 2 0 DO 4 ALLOT I C, LOOP")
    assert forth.send("t2 4 + C@ . t2 9 + C@ . HERE t2 - .") == "0 1 10 "
    still_works(forth)


# ---- 5: REFILL inside a typed line ------------------------------------------------------
def test_refill_in_a_typed_line_after_else(forth):
    forth.send(": PT10 REFILL DROP REFILL DROP ;")
    forth.child.send('-1 [IF] 2 [ELSE] 3 S" [THEN] 4 PT10 IGNORED TO END OF LINE"\r')
    forth.child.send("      [THEN]          \\ in case [THEN] in the string is not seen\r")
    assert forth.send("   .S 2DROP").endswith("<2> 2 4 ")
    still_works(forth)


# ---- 6, 7, 12, 13: gforth's answers -------------------------------------------------------
def test_trailing_o_is_a_digit_from_base_25(forth):
    assert forth.send("36 BASE ! ZO . DECIMAL 25 BASE ! 1O . DECIMAL 24 BASE ! 17O DECIMAL .") \
        == "ZO 1O 15 "
    forth.send("DECIMAL")
    assert forth.send('S" ADDRESS-UNIT-BITS" ENVIRONMENT? . .') == "-1 8 "


def test_interpreted_strings_keep_their_length(forth):
    text = "".join(chr(65 + k % 26) for k in range(140))
    assert forth.send(f'S" {text}" NIP .') == "140 "
    assert forth.send(f'S\\" {text}" TYPE') == text
    assert forth.send('S" abc" S" de" S" f" TYPE TYPE TYPE') == "fdeabc"
    long = "y" * 240                                  # a line holds 255 characters
    assert forth.send(f'S" {long}" NIP .') == "240 "


def test_negative_allot_into_a_header_forgets_that_word(forth):
    forth.send("CREATE buf 100 ALLOT  -110 ALLOT  : sq dup * ;")
    assert forth.send("7 sq .") == "49 "
    assert forth.send("1 2 3 ROT . . . 6 3 AND .") == "1 3 2 2 "
    assert forth.reply("buf").error == "undefined word: buf"
    still_works(forth)


def test_postponed_immediate_word_runs_in_compile_state(forth):
    forth.send(': ps POSTPONE S" ;  : t [ ps XY" ] ;')
    assert forth.send("t TYPE") == "XY"
    forth.send(": ENDIF POSTPONE THEN ; IMMEDIATE  : z 1 IF 5 . ENDIF ;")
    assert forth.send("z 1 IF 6 . ENDIF") == "5 6 "
    still_works(forth)
