"""The kernel's own conventions: numbers, loops, vocabularies, case, tools,
FORGET/MARKER and interrupt vectors, the banner."""
import re

from harness.machine.kernel_layout import chain_of
from harness.machine.machine import KERNEL
from harness.machine.scripted_machine import read_kernel_map


def test_banner_names_system_memory_disk(forth):
    assert "PDP-11/23 FORTH" in forth.banner
    free = int(re.search(r"(\d+) bytes free", forth.banner).group(1))
    assert free >= 16 * 1024  # issue 12: at least 16 KB free at boot
    assert "RL02" in forth.banner
    assert forth.send("UNUSED U.") == f"{free} "


def test_numbers_octal_negative_base(forth):
    assert forth.send("177546O .") == "-154 "
    assert forth.send("177546O U.") == "65382 "
    assert forth.send("-17 .") == "-17 "
    assert forth.send("HEX 1F . 10O . DECIMAL") == "1F 8 "
    assert forth.send("OCTAL 777 . 10 DECIMAL .") == "777 8 "
    assert forth.send("2 BASE ! 101 DECIMAL .") == "5 "
    assert forth.send("-32768 . 65535 U.") == "-32768 65535 "
    assert "undefined word: 12X" in forth.reply("12X").error


def test_plus_loop_counts_down_through_zero(forth):
    assert forth.send("0 3 DO I . -1 +LOOP") == "3 2 1 0 "  # at the terminal too
    before = forth.send("HERE .")
    assert forth.send("1 IF 5 ELSE 6 THEN .") == "5 "
    assert forth.send("3 BEGIN DUP . 1- DUP 0= UNTIL DROP") == "3 2 1 "
    assert forth.send("2 0 DO 2 0 DO J I + . LOOP LOOP") == "0 1 1 2 "
    assert forth.send("HERE .") == before
    forth.send(": DOWN 0 3 DO I . -1 +LOOP ;")
    assert forth.send("DOWN") == "3 2 1 0 "
    forth.send(": UP2 10 0 DO I . 3 +LOOP ;")
    assert forth.send("UP2") == "0 3 6 9 "
    forth.send(": NEST 2 0 DO 3 0 DO J 10 * I + . LOOP LOOP ;")
    assert forth.send("NEST") == "0 1 2 10 11 12 "
    forth.send(": QDO 0 ?DO I . LOOP ;")
    assert forth.send("0 QDO 2 QDO") == "0 1 "


def test_double_cell_and_eis(forth):
    assert forth.send("1000 1000 UM* D.") == "1000000 "
    assert forth.send("-1000 1000 M* D.") == "-1000000 "
    assert forth.send("34464 1 7 UM/MOD . .") == "14285 5 "
    assert forth.send("7 S>D 2 SM/REM . .") == "3 1 "
    assert forth.send("-7 S>D 2 SM/REM . .") == "-3 -1 "
    assert forth.send("-7 S>D 2 FM/MOD . .") == "-4 1 "
    assert forth.send("100 200 300 */ .") == "66 "
    assert forth.send("1 2 3 4 D+ D.") == "393220 "  # 0x40004 + ... = (1+3) + (2+4)*65536
    assert forth.send("-5 S>D DABS D.") == "5 "
    assert forth.send('S" abc" S" abd" COMPARE . S" abc" S" abc" COMPARE .') == "-1 0 "


def test_case_insensitive_names_kept_as_written(forth):
    forth.send(": MixedCase 42 ;")
    assert forth.send("mixedcase . MIXEDCASE .") == "42 42 "
    assert "MixedCase" in forth.send("WORDS")
    assert forth.send("1 dup + .") == "2 "


def test_vocabularies_forth79(forth):
    forth.send("VOCABULARY TOOLS  TOOLS DEFINITIONS  : HAMMER 7 ; FORTH DEFINITIONS")
    assert "undefined word: HAMMER" in forth.reply("HAMMER").error
    assert forth.send("TOOLS HAMMER . FORTH") == "7 "
    # vocabulary words are immediate: usable inside a definition
    forth.send(": USE-HAMMER TOOLS HAMMER FORTH 1+ ;")
    assert forth.send("USE-HAMMER .") == "8 "
    # ":" sets CONTEXT to CURRENT
    forth.send("TOOLS : AFTER-COLON 1 ;")
    assert "undefined word: HAMMER" in forth.reply("HAMMER").error
    # CODE sets CONTEXT to ASSEMBLER; END-CODE back
    assert forth.send("CODE NOP-WORD CONTEXT @ ' ASSEMBLER >BODY = . 134O , END-CODE") == "-1 "
    assert forth.send("NOP-WORD CONTEXT @ ' FORTH >BODY = .") == "-1 "


def test_forget_and_marker_restore_vectors(forth):
    forth.send("MARKER SCRATCH")
    forth.send("CODE MY-HANDLER 2 , END-CODE")  # RTI
    forth.send("' MY-HANDLER 300O !")
    out = forth.send("SCRATCH")
    assert "vector 000300 restored to its default handler" in out
    assert forth.send("300O @ 1300O = .") == "-1 "
    assert "undefined word" in forth.reply("MY-HANDLER").error
    forth.send(": TEMP1 1 ; : TMP2 2 ; : TEMPO3 3 ; : T4 4 ;")  # all four chains
    assert forth.send("WORDS").startswith("T4 TEMPO3 TMP2 TEMP1 ")
    forth.send("FORGET TEMP1")
    for name in ("TEMP1", "TMP2", "TEMPO3", "T4"):
        assert "undefined word" in forth.reply(name).error
    assert "cannot forget kernel words" in forth.reply("FORGET DUP").error


def test_tools(forth):
    assert forth.send("1 2 3 .S DROP DROP DROP") == "<3> 1 2 3 "
    forth.send(": SQUARE DUP * ;")
    assert "SQUARE is : DUP * EXIT ;" in forth.send("SEE SQUARE")
    assert "is CODE at" in forth.send("SEE DUP")
    assert "CONSTANT 32" in forth.send("SEE BL")
    assert re.search(r"48 +49 +50 .*012", forth.send('S" 012" DROP 3 DUMP'))
    forth.send("VARIABLE V  5 V !  3 V +!")
    assert forth.send("V @ . V ?") == "8 8 "
    forth.send("5 VALUE FIVE  7 TO FIVE")
    assert forth.send("FIVE .") == "7 "


def test_appendix_words(forth):
    forth.send("3 CON THREE  9 VAR NINE  4 ARRAY QUAD")
    assert forth.send("THREE . NINE @ . QUAD 6 + @ .") == "3 9 0 "
    assert forth.send("QUAD 2+ 1SET QUAD 2+ @ .") == "1 "
    forth.send(": COUNTDOWN 3 BEGIN DUP . 1- DUP 0= END DROP ;")
    assert forth.send("COUNTDOWN") == "3 2 1 "


def test_priority_zero_after_boot(forth):
    assert forth.send("177776O @ 340O AND .") == "0 "  # PSW bits 7-5


def test_typed_ahead_lines_are_kept(forth):
    """Receive is interrupt-driven: lines typed while a word runs are buffered."""
    from harness.machine.machine import OK
    forth.send(": BUSY 30000 0 DO LOOP ;")
    forth.child.send("BUSY\r1 2 + .\r3 4 + .\r")
    replies = []
    for _ in range(3):
        forth.child.expect(OK)
        replies.append(forth.child.before)
    assert replies[1].endswith(" 3 ") and replies[2].endswith(" 7 ")


def test_line_editing(forth):
    # backspace and delete remove a character, ^U the whole line
    # (the echo of the erasing stays in the output: check how it ends)
    assert forth.send("1 2 +\b- .").endswith(" \b- . -1 ")
    assert forth.send("1 2 +\x7f- .").endswith(" \b- . -1 ")
    assert forth.send("99 DROP\x15 5 .").endswith("5 . 5 ")
    assert forth.send("DEPTH .").endswith("0 ")


def test_code_words_with_the_resident_assembler(forth):
    forth.send("CODE TWICE S ) ASL, NEXT, END-CODE")
    assert forth.send("21 TWICE .") == "42 "
    # block 1008 style: the next ":" ends the CODE word
    forth.send("CODE THRICE R0 S ) MOV, S ) R0 ADD, S ) R0 ADD, NEXT,")
    forth.send(": NINE 3 THRICE ;")
    assert forth.send("NINE .") == "9 "
    r = forth.reply("CODE BAD R0 MOV,")
    assert r.error == "wrong number of operands: MOV,"
    assert forth.send("1 2 + .") == "3 "
    forth.send(": KONST CREATE , ;CODE S -) W ) MOV, NEXT, END-CODE")
    assert forth.send("5 KONST FIVE FIVE .") == "5 "


def test_harness_reports_a_halt():
    """A HALT reaches the simulator prompt: the harness says so, not a timeout."""
    import pytest
    from harness.machine.machine import Machine, MachineHalted
    with Machine() as m:
        with pytest.raises(MachineHalted):
            m.send("CODE STOP HALT, END-CODE STOP")


def test_interrupt_handler_in_code_then_forget(forth):
    """The appendix's pattern: register-saving macros as colon definitions that
    assemble, a CODE word ending in RTI installed with ' into the clock vector,
    FORGET restores it. The clock is enabled through LKS where it exists (the
    project's KW11-L); the stock 11/23 has no LKS (the bus error is CAUGHT) and
    always interrupts."""
    forth.send_lines("""MARKER CLOCK-TEST
: Save-Regs ASSEMBLER RP -) R0 MOV, RP -) T MOV, RP -) W MOV, FORTH ;
: Restore-Regs ASSEMBLER W RP )+ MOV, T RP )+ MOV, R0 RP )+ MOV, FORTH ;
VARIABLE TICKS
CODE Tick Save-Regs TICKS @# INC, Restore-Regs RTI,
: LKS-ON 100O 177546O ! ;
: CLOCK-ON ['] LKS-ON CATCH DROP ;
: Install ' Tick 100O ! CLOCK-ON ;
: WAIT-TICKS ( n -- ) TICKS @ + BEGIN DUP TICKS @ - 0< UNTIL DROP ;""")
    forth.send("Install 3 WAIT-TICKS")
    assert int(forth.send("TICKS @ .")) >= 3
    assert "vector 000100 restored" in forth.send("CLOCK-TEST")
    assert forth.send("100O @ 1100O = .") == "-1 "


def kernel_cell(name):
    """The address of one of the kernel's variables (build/kernel.map)."""
    return read_kernel_map(KERNEL.with_suffix(".map"))[name]


def test_typed_ahead_beyond_the_ring_arrives_whole(forth):
    """More than 511 characters typed while a word runs: the receive interrupt sends
    XOFF before the ring is full, the terminal side waits, and every line arrives
    (issue 23); nothing is reported lost."""
    # the word runs until XOFF has gone out (XOFF-HELD set), however late the host's
    # characters come; then KEY drains the ring, sends XON, and the rest arrive
    forth.send(f": UNTIL-XOFF BEGIN {kernel_cell('XOFF-HELD')} @ UNTIL ;")
    forth.child.send("UNTIL-XOFF\r" + "".join(f"{n} DROP {'1 DROP ' * 10}\r" for n in range(9)))
    for n in range(9):
        forth.child.expect(f"{n} DROP (1 DROP ){{10}} +ok\r\n")
    assert "lost" not in forth.child.before
    assert forth.send("2 2 + .") == "4 "


def test_ring_overflow_is_reported_when_the_terminal_ignores_xoff(forth):
    """RXLOST stays as the guard: with XOFF-HELD set (as if XOFF had gone out and the
    terminal kept sending), the ring fills, the excess is dropped and the loss is
    reported at the next line."""
    # the word runs until a character has been dropped
    forth.send(f": UNTIL-LOST BEGIN {kernel_cell('RXLOST')} @ UNTIL ;")
    forth.child.send(f"1 {kernel_cell('XOFF-HELD')} ! UNTIL-LOST\r" + ("1 DROP " * 11 + "\r") * 9)
    forth.child.expect("characters lost: typed too far ahead")
    forth.child.send("\r")  # ends whatever line the ring cut short
    forth.child.send(".( in step)\r")
    forth.child.expect(r"in step ok\r\n")
    assert forth.send("2 2 + .") == "4 "


def test_hashed_chains_lookup(forth):
    """Issue 19: a word list keeps 32 chains, a name's chain picked by its
    upper-cased first character and its length (harness.machine.kernel_layout's
    chain_of, the kernel's CHAIN-OFFSET): names sharing a chain, names typed in
    another case, a WORDLIST's SEARCH-WORDLIST, WORDS and FORGET across chains."""
    assert chain_of("AXY") == chain_of("cq")  # 'A'+6 = 'C'+4: one chain
    forth.send("MARKER HASHED")
    forth.send(": AXY 1 ; : AXZ 2 ; : cq 3 ; : Q 4 ;")
    assert forth.send("AXY . axz . CQ . q .") == "1 2 3 4 "
    assert forth.send("1 dup + . 5 6 Swap drop .") == "2 6 "  # kernel words, any case
    for name in ("AXY", "AXZ", "cq", "Q", "DUP", "SEARCH-WORDLIST", "."):
        # each newest header heads the chain chain_of names (DUP: below ours)
        chain = numbers(forth.send(f'S" {name}" FORTH-WORDLIST CHAIN FORTH-WORDLIST - . 2DROP'))
        assert chain == [2 * chain_of(name)]
    assert forth.send("FORTH-WORDLIST 2 chain_of_cq * + @ 2+ COUNT 31 AND TYPE".replace(
        "chain_of_cq", str(chain_of("cq")))) == "cq"
    assert forth.send("WORDS").startswith("Q cq AXZ AXY HASHED ")
    forth.send("WORDLIST CONSTANT WL  WL SET-CURRENT")
    forth.send(": AXY 10 ; : BQ 20 ; FORTH-WORDLIST SET-CURRENT")
    assert forth.send('S" axy" WL SEARCH-WORDLIST . EXECUTE .') == "-1 10 "
    assert forth.send('S" CQ" WL SEARCH-WORDLIST .') == "0 "
    assert forth.send('S" " WL SEARCH-WORDLIST .') == "0 "
    forth.send("HASHED")
    for name in ("AXY", "AXZ", "cq", "Q", "WL"):
        assert "undefined word" in forth.reply(name).error
    assert forth.send("1 dup + .") == "2 "


def numbers(text):
    return [int(n) for n in text.split()]
