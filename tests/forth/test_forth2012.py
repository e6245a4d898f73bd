"""Forth-2012 word sets (16-bit cells), word set by word set, through the
console: the edge cases the standard spells out, and the coexistence with the
FORTH-79 conventions the 1983 blocks need (tests/forth/test_language.py)."""


def lines(forth, *typed):
    """Type lines that get no " ok" of their own (a REFILL reads them), then
    the last line; its reply."""
    for line in typed[:-1]:
        forth.child.send(line + "\r")
    return forth.send(typed[-1])


# ---- CORE -----------------------------------------------------------------
def test_core_number_prefixes_and_double_literals(forth):
    assert forth.send("#12 $1F %101 'a' .S 2DROP 2DROP") == "<4> 12 31 5 97 "
    assert forth.send("HEX #10 . $-1f . 'Z' . DECIMAL") == "A -1F 5A "
    assert forth.send("#-19 . %-11 . ''' .") == "-19 -3 39 "
    assert forth.send("1. D. -12345. D. 70000. D.") == "1 -12345 70000 "
    assert forth.send(": DL 1234567. -2. ; DL D. D.") == "-2 1234567 "
    assert forth.send("$-12AbCdEf. D. 177546O .") == "-313249263 -154 "
    for bad in ("$", "#-", "1..", "'ab'", "-.", "%102"):
        assert "undefined word: " + bad in forth.reply(bad).error


def test_core_find_leaves_c_addr_0(forth):
    forth.send(': C-NOSUCH C" NOSUCH-WORD" ;')
    assert forth.send("C-NOSUCH FIND SWAP C-NOSUCH = . .") == "-1 0 "
    assert forth.send("' DUP C-NOSUCH DROP HERE ! HERE FIND DROP . ") != ""
    forth.send(': C-IF C" IF" ;  : C-DUP C" dup" ;')
    assert forth.send("C-IF FIND NIP . C-DUP FIND SWAP ' DUP = . .") == "1 -1 -1 "


def test_core_loops_at_their_boundaries(forth):
    forth.send("VARIABLE STEP  : PL ( limit start step -- ) STEP ! ?DO I . STEP @ +LOOP ;")
    assert forth.send("10 0 3 PL") == "0 3 6 9 "
    assert forth.send("0 10 -3 PL") == "10 7 4 1 "
    assert forth.send("0 0 -1 PL") == ""  # ?DO: limit = start runs nothing
    assert forth.send("-32768 32767 -32768 PL") == "32767 -1 "  # crosses -32768/32767
    assert forth.send("0 -1 32767 PL") == "-1 "
    forth.send(": CD 0 3 DO I . -1 +LOOP ;  : LV 10 0 DO I DUP . 3 = IF LEAVE THEN LOOP ;")
    assert forth.send("CD LV") == "3 2 1 0 0 1 2 3 "
    assert forth.send("0 3 DO I . -1 +LOOP") == "3 2 1 0 "  # typed at the prompt


def test_core_division_signs(forth):
    # SM/REM rounds towards zero, FM/MOD floors; / MOD */ use SM/REM (FLOORED false)
    assert forth.send("7 S>D 2 SM/REM . . -7 S>D 2 SM/REM . .") == "3 1 -3 -1 "
    assert forth.send("7 S>D -2 SM/REM . . -7 S>D -2 SM/REM . .") == "-3 1 3 -1 "
    assert forth.send("7 S>D 2 FM/MOD . . -7 S>D 2 FM/MOD . .") == "3 1 -4 1 "
    assert forth.send("7 S>D -2 FM/MOD . . -7 S>D -2 FM/MOD . .") == "-4 -1 3 -1 "
    assert forth.send("-7 2 / . -7 2 MOD . -7 2 5 */ .") == "-3 -1 -2 "
    assert forth.send('S" FLOORED" ENVIRONMENT? . .') == "-1 0 "


def test_core_environment_answers_match_the_system(forth):
    def env(name):
        return forth.send(f'S" {name}" ENVIRONMENT? .S 2DROP')
    assert env("MAX-N") == "<2> 32767 -1 "
    assert env("MAX-U") == "<2> -1 -1 "
    assert env("ADDRESS-UNIT-BITS") == "<2> 8 -1 "      # issue 16: a byte
    assert env("/COUNTED-STRING") == "<2> 255 -1 "
    assert forth.send('S" MAX-D" ENVIRONMENT? . D.') == "-1 2147483647 "
    assert forth.send('S" MAX-UD" ENVIRONMENT? . UD.'.replace("UD.", "<# #S #> TYPE")) == "-1 4294967295"
    assert forth.send('S" NO-SUCH-QUERY" ENVIRONMENT? .') == "0 "
    # STACK-CELLS is what the data stack holds: one more is stack overflow
    forth.send('S" STACK-CELLS" ENVIRONMENT? DROP CONSTANT #CELLS')
    forth.send(": FILL-STACK ( n -- ) 0 ?DO I LOOP ;")
    assert forth.send("#CELLS .") == "216 "
    forth.send(": CLEAR S0 SP! ;")
    assert forth.send("#CELLS FILL-STACK CLEAR") == ""
    assert "stack overflow" in forth.reply("#CELLS 1+ FILL-STACK").error
    # PAD holds /PAD characters below the dictionary's end
    assert forth.send('S" /PAD" ENVIRONMENT? DROP PAD + UNUSED HERE + 160 + U> 0= .') == "-1 "


def test_core_recurse_source_id_and_odd_here(forth):
    forth.send(":NONAME ( n -- n! ) DUP 1 > IF DUP 1- RECURSE * THEN ; CONSTANT FACT")
    assert forth.send("5 FACT EXECUTE .") == "120 "
    assert forth.send('SOURCE-ID . S" SOURCE-ID" EVALUATE .') == "0 -1 "
    # a control structure typed with HERE odd
    assert forth.send("HERE 1 AND 0= IF 0 C, THEN HERE 1 AND . 1 IF 5 . THEN HERE 1 AND .") \
        == "1 5 1 "
    forth.send("ALIGN")
    # a parsing word that misses names the missing word, not itself (issue 9)
    for line in ("SEE nosuch", "' nosuch", "FORGET nosuch", ": X POSTPONE nosuch ;"):
        assert forth.reply(line).error == "undefined word: nosuch", line


# ---- EXCEPTION --------------------------------------------------------------
def test_exception_catch_restores_the_input_source(forth):
    # the rest of the evaluated string is not interpreted; the typed line goes on
    out = forth.send("S\" 1 2 XQQQ 3\" ' EVALUATE CATCH . 77 .")
    assert out == "-13 77 "
    forth.send(': INNER S" 5 ABORT 6" EVALUATE ;  : OUTER S" 1 INNER 2" EVALUATE ;')
    assert forth.send("' OUTER CATCH . 8 .") == "-1 8 "
    forth.send(': T10 77 SWAP ABORT" not shown" ;')
    assert forth.send("4 5 ' T10 CATCH . . .") == "-2 77 4 "  # caught: no message
    assert forth.send("' DUP CATCH") == ""  # nothing to dup: no stack check inside
    forth.send("S0 SP!")
    assert "undefined word: NOSUCH" in forth.reply("1 2 NOSUCH 3").error
    assert forth.send("DEPTH .") == "0 "


def test_exception_error_in_a_loaded_block_names_block_and_line(forth):
    for line in ("EDITOR 1500 WIPE", "0 P ( test block )", "1 P 1 2 +", "2 P NOSUCHWORD",
                 "FORTH"):
        forth.send(line)
    err = forth.reply("1500 LOAD").error.strip()
    assert err == "undefined word: NOSUCHWORD in block 1500 line 2"
    assert forth.send("BLK @ .") == "0 "


# ---- CORE EXT ------------------------------------------------------------------
def test_core_ext_case_defer_value(forth):
    forth.send(": CS CASE 1 OF 11 ENDOF 2 OF 22 ENDOF DUP 100 * SWAP ENDCASE ;")
    assert forth.send("1 CS . 2 CS . 3 CS .") == "11 22 300 "
    forth.send("DEFER ACT  : RUN-ACT ACT ;")
    assert "DEFER without an action" in forth.reply("RUN-ACT").error
    forth.send("' DUP IS ACT  : SET-ACT IS ACT ;  : GET-ACT ACTION-OF ACT ;")
    assert forth.send("3 RUN-ACT . . ' ACT DEFER@ ' DUP = .") == "3 3 -1 "
    forth.send("' NEGATE SET-ACT")
    assert forth.send("4 ACT . GET-ACT ' NEGATE = . ACTION-OF ACT ' NEGATE = .") == "-4 -1 -1 "
    forth.send("' 1+ ' ACT DEFER!")
    assert forth.send("4 ACT .") == "5 "
    forth.send("10 VALUE V1  : SET-V1 TO V1 ;")
    assert forth.send("V1 . 20 TO V1 V1 . 30 SET-V1 V1 .") == "10 20 30 "
    forth.send("SYNONYM V2 V1  SYNONYM ACT2 ACT")  # TO and IS reach through a SYNONYM
    assert forth.send("40 TO V2 V1 . V2 . ' 1- IS ACT2 5 ACT .") == "40 40 4 "


def test_core_ext_strings_and_buffers(forth):
    forth.send(': CQ C" counted" ;  : SQ S\\" a\\tb\\x41\\\\\\"" ;')
    assert forth.send("CQ COUNT TYPE CQ C@ .") == "counted7 "
    assert forth.send("SQ DUP . OVER 1+ C@ . TYPE") == '6 9 a\tbA\\"'
    assert forth.send('S\\" x\\ny" DUP . DROP 1+ C@ .') == "4 13 "
    forth.send("3 CELLS BUFFER: BUF3")
    assert forth.send("BUF3 3 CELLS + HERE = . BUF3 1 AND .") == "-1 0 "
    assert forth.send('0 0 <# S" abc" HOLDS #> TYPE') == "abc"
    forth.send(": R2 2>R 2R@ 2R> ;")
    assert forth.send("1 2 R2 .S 2DROP 2DROP") == "<4> 1 2 1 2 "
    assert forth.send(": PN PARSE-NAME TYPE ; PN   word") == "word"


def test_core_ext_refill_and_save_input(forth):
    # REFILL at the terminal reads the next line into the input buffer
    forth.send(": NEXT-LINE REFILL . SOURCE TYPE ;")
    assert lines(forth, "NEXT-LINE", "2 3 + .").endswith("-1 2 3 + .5 ")
    assert forth.send('S" REFILL" EVALUATE .') == "0 "
    forth.send("VARIABLE SKIP  0 SKIP !  : SI SKIP @ >IN +! 15 SKIP ! ;")
    forth.send(': SS S" SAVE-INPUT SI RESTORE-INPUT 12345" ;')
    assert forth.send("SS EVALUATE . . SKIP @ .") == "2345 0 15 "
    assert forth.send("0 SAVE-INPUT DROP 6 RESTORE-INPUT . DEPTH .") == "-1 0 "


# ---- DOUBLE ------------------------------------------------------------------------
def test_double_words(forth):
    forth.send("1 2 2CONSTANT C12  2VARIABLE DV  5. 2VALUE DVAL")
    assert forth.send("C12 . . -3. DV 2! DV 2@ D.") == "2 1 -3 "
    assert forth.send("DVAL D. 7. TO DVAL DVAL D. : SETD TO DVAL ; 8. SETD DVAL D.") == "5 7 8 "
    assert forth.send(": L2 [ 70000. ] 2LITERAL ; L2 D.") == "70000 "
    assert forth.send("5. 7. D- D. -1. 1. D< . 1. -1. DU< . 0. D0= . -1. D0< .") \
        == "-2 -1 -1 -1 -1 "
    assert forth.send("-3. D2/ D. 100000. D2* D. 3. 5. DMAX D. 3. 5. DMIN D.") \
        == "-2 200000 5 3 "
    assert forth.send("100000. 3 M+ D. 70000. D>S . 1. 2. 3. 2ROT D. D. D.") \
        == "100003 4464 1 3 2 "
    # M*/ keeps a triple-cell product: no overflow before the division
    assert forth.send("2147483647. 32767 32767 M*/ D.") == "2147483647 "
    assert forth.send("-5. 7 11 M*/ D. 5. -7 11 M*/ D.") == "-3 -3 "
    assert forth.send("1000000. 2 3 M*/ D. 12345. 10 D.R") == "666666      12345"


# ---- STRING -----------------------------------------------------------------
def test_string_words(forth):
    forth.send(': S1 S" abcdefgh" ;')
    assert forth.send('S1 S" def" SEARCH . TYPE') == "-1 defgh"
    assert forth.send('S1 S" dex" SEARCH . TYPE') == "0 abcdefgh"
    assert forth.send('S1 S" " SEARCH . . DROP') == "-1 8 "
    assert forth.send('S" ab   " -TRAILING . DROP S"    " -TRAILING . DROP') == "2 0 "
    assert forth.send("PAD 3 CHAR x FILL PAD 1+ 1 BLANK PAD 3 TYPE") == "x x"
    assert forth.send(': SL [ S" lit" ] SLITERAL ; SL TYPE') == "lit"
    forth.send("CREATE DST 40 ALLOT")
    forth.send('S" Robot" S" who" REPLACES')
    assert forth.send('S" %who% 100%% %nobody%" DST 40 SUBSTITUTE . TYPE') \
        == "1 Robot 100% %nobody%"
    assert forth.send('S" %who%" DST 3 SUBSTITUTE . 2DROP') == "-1 "
    assert forth.send('S" 5%" DST UNESCAPE TYPE') == "5%%"


# ---- TOOLS and TOOLS EXT ---------------------------------------------------------
def test_tools_conditional_compilation(forth):
    assert forth.send("1 [IF] 11 [ELSE] 22 [THEN] .") == "11 "
    assert forth.send("0 [IF] 11 [ELSE] 22 [THEN] .") == "22 "
    assert forth.send("0 [IF] 1 [IF] 11 [ELSE] 12 [THEN] [ELSE] 22 [then] .") == "22 "
    # skipping goes on over the following lines typed at the terminal
    assert lines(forth, "0 [IF] 11", "12 13", "[ELSE] 14 [THEN] .").endswith("14 ")
    assert forth.send("[DEFINED] DUP . [UNDEFINED] DUP . [DEFINED] NO-SUCH .") == "-1 0 0 "
    assert forth.send(": CC [ 1 ] [IF] 1 [ELSE] 2 [THEN] ; CC .") == "1 "


def test_tools_control_flow_and_return_stack(forth):
    assert forth.send(": AH AHEAD 1 . THEN 2 . ; AH") == "2 "
    forth.send(": ?REPEAT 0 CS-PICK POSTPONE UNTIL ; IMMEDIATE")
    forth.send(": ?DONE POSTPONE IF 1 CS-ROLL ; IMMEDIATE")
    forth.send(": CNT >R BEGIN R@ ?DONE R@ . R> 1- >R REPEAT R> DROP ;")
    assert forth.send("3 CNT") == "3 2 1 "
    forth.send(": NR 1 2 3 3 N>R 9 NR> ;")
    assert forth.send("NR .S 2DROP 2DROP DROP") == "<5> 9 1 2 3 3 "


def test_tools_name_tokens_synonym_traverse(forth):
    forth.send(": SY1 7 ;  SYNONYM SY2 SY1  SYNONYM MY-IF IF")
    assert forth.send("SY2 . : SY3 1 MY-IF 8 . THEN ; SY3") == "7 8 "
    forth.send("WORDLIST CONSTANT WL  WL SET-CURRENT : AA 1 ; : BBB 2 ; : AA 3 ;"
               " FORTH-WORDLIST SET-CURRENT")
    forth.send(": SHOW ( nt -- f ) NAME>STRING TYPE SPACE TRUE ;")
    shown = forth.send("' SHOW WL TRAVERSE-WORDLIST").split()
    # every word once; the order is the word list's chains' (Forth-2012 leaves it open)
    assert sorted(shown) == ["AA", "AA", "BBB"]
    forth.send(": FIRST ( n nt -- nt false ) NIP FALSE ;")
    forth.send(': AA-NT 0 ' + "['] FIRST WL TRAVERSE-WORDLIST ;")
    assert forth.send("AA-NT NAME>INTERPRET EXECUTE .") in ("3 ", "2 ")
    assert forth.send("AA-NT NAME>COMPILE ' COMPILE, = . DROP") == "-1 "


# ---- SEARCH and the FORTH-79 vocabularies --------------------------------------
def test_search_order_words(forth):
    assert forth.send("GET-ORDER . FORTH-WORDLIST = . FORTH-WORDLIST = .") == "2 -1 -1 "
    forth.send("WORDLIST CONSTANT W2  W2 SET-CURRENT  : W2WORD 42 ; FORTH-WORDLIST SET-CURRENT")
    assert "undefined word: W2WORD" in forth.reply("W2WORD").error
    assert forth.send("GET-ORDER W2 SWAP 1+ SET-ORDER W2WORD . PREVIOUS") == "42 "
    assert forth.send('S" W2WORD" W2 SEARCH-WORDLIST . EXECUTE .') == "-1 42 "
    assert forth.send('S" W2WORD" FORTH-WORDLIST SEARCH-WORDLIST .') == "0 "
    assert forth.send("ONLY GET-ORDER . FORTH-WORDLIST = . ALSO GET-ORDER NIP NIP .") == "1 -1 2 "
    forth.send(": PREVIOUS2 PREVIOUS PREVIOUS ;")
    assert "search-order underflow" in forth.reply("ONLY PREVIOUS2").error
    assert forth.send("GET-ORDER . 2DROP") == "2 "  # the error left the boot order
    assert "search-order overflow" in forth.reply("ALSO ALSO ALSO ALSO ALSO ALSO ALSO ALSO").error
    forth.send("ONLY FORTH ALSO DEFINITIONS")
    assert forth.send("ORDER") == "\r\nFORTH FORTH   definitions: FORTH "
    # : leaves a standard program's order alone
    assert forth.send("GET-ORDER W2 SWAP 1+ SET-ORDER : COL 1 ; CONTEXT @ W2 = . PREVIOUS") \
        == "-1 "


def test_search_coexists_with_forth79_vocabularies(forth):
    # a vocabulary word replaces the first word list (CONTEXT); FORTH is searched after it
    assert forth.send("ASSEMBLER GET-ORDER . ' ASSEMBLER >BODY = . FORTH-WORDLIST = . FORTH") \
        == "2 -1 -1 "
    assert forth.send("ALSO ASSEMBLER ORDER PREVIOUS").startswith("\r\nASSEMBLER FORTH FORTH")
    # ":" sets CONTEXT to CURRENT (both vocabularies), as the 1983 blocks expect
    forth.send("EDITOR : AFTER-EDITOR ;")
    assert forth.send("CONTEXT @ FORTH-WORDLIST = .") == "-1 "
    # the interpreter finds the assembler's words only while ASSEMBLER is in the order
    assert "undefined word: MOV," in forth.reply("MOV,").error
    assert forth.send(": M1 ASSEMBLER R0 R1 MOV, FORTH ; ' M1 DROP 1 .") == "1 "
    assert forth.send("FORTH GET-ORDER . = .") == "2 -1 "
    # after ONLY, a vocabulary other than FORTH still chains to FORTH (FORTH-79)
    assert forth.send("ONLY ASSEMBLER GET-ORDER . ' ASSEMBLER >BODY = . FORTH-WORDLIST = . "
                      "FORTH GET-ORDER . 2DROP") == "2 -1 -1 2 "
    assert forth.send("ONLY FORTH GET-ORDER . FORTH-WORDLIST = .") == "1 -1 "
    assert forth.send("ONLY FORTH DEFINITIONS 1 .") == "1 "
    assert forth.send(": M2 ASSEMBLER R0 R1 MOV, ( a comment ) FORTH ; 2 .") == "2 "
    forth.send("ONLY FORTH ALSO DEFINITIONS")


# ---- FACILITY -----------------------------------------------------------------
def test_facility_structures(forth):
    forth.send("BEGIN-STRUCTURE POINT  FIELD: P.X  FIELD: P.Y  CFIELD: P.TAG  END-STRUCTURE")
    assert forth.send("POINT . 0 P.X . 0 P.Y . 0 P.TAG .") == "5 0 2 4 "
    forth.send("BEGIN-STRUCTURE PAIR  POINT +FIELD PR.A  CFIELD: PR.C  FIELD: PR.B  END-STRUCTURE")
    assert forth.send("PAIR . 0 PR.B .") == "8 6 "
    forth.send("CREATE PT POINT ALLOT  3 PT P.X !  4 PT P.Y !  7 PT P.TAG C!")
    assert forth.send("PT P.X @ . PT P.Y @ . PT P.TAG C@ .") == "3 4 7 "


def test_facility_time_from_the_simulated_clock(forth):
    assert forth.send("TIME&DATE . . . . . .") == "1983 4 7 0 0 0 "
    # the kernel's clock handler counts ticks while the clock interrupt is on
    forth.send("100O 177546O !  1100 MS  0 177546O !")
    sec = forth.send("TIME&DATE 2DROP 2DROP DROP .")
    assert sec == "1 "
    assert forth.send("EKEY? . 65 EKEY>CHAR . . EMIT? .") == "0 -1 65 -1 "


# ---- BLOCK and BLOCK EXT ---------------------------------------------------------
def put_block(forth, n, text):
    forth.send(f'{n} BUFFER 1024 BLANK  S" {text}" {n} BLOCK SWAP CMOVE UPDATE')


def test_block_refill_save_input_and_update(forth):
    # REFILL in a block goes on with the next block
    put_block(forth, 1601, "1 2 REFILL 4 5")
    put_block(forth, 1602, "10 11")
    assert forth.send("1601 LOAD .S 2DROP 2DROP DROP") == "<5> 1 2 -1 10 11 "
    # SAVE-INPUT in one block, REFILL into the next, RESTORE-INPUT back: once
    forth.send("VARIABLE PASSES  0 PASSES !")
    # (REFILL's and RESTORE-INPUT's flags stay: the source changes under them)
    put_block(forth, 1603, "SAVE-INPUT REFILL")
    put_block(forth, 1604, "DROP 1 PASSES +! PASSES @ 2 < [IF] RESTORE-INPUT [ELSE] [THEN] 7")
    assert forth.send("1603 LOAD PASSES @ . .S 2DROP") == "2 <2> 0 7 "
    # LOAD makes the loaded block the one UPDATE marks
    put_block(forth, 1605, "SOURCE DROP")
    forth.send("FLUSH 1606 BUFFER 1024 BLANK  1605 LOAD  CHAR x SWAP C! UPDATE FLUSH")
    assert forth.send("1605 BLOCK C@ EMIT 1606 BLOCK C@ .") == "x0 "
    # THRU loads in order; BLK names the block being loaded
    put_block(forth, 1607, "BLK")
    put_block(forth, 1608, "@")
    assert forth.send("1607 1608 THRU .") == "1608 "
    # \ in a block skips to the end of its 64-character line; >IN moves within the block
    forth.send("1609 BUFFER 1024 BLANK  S\" 1 \\ 2\" 1609 BLOCK SWAP CMOVE"
               "  S\" 3 2 >IN +! 4 5\" 1609 BLOCK 64 + SWAP CMOVE UPDATE")
    assert forth.send("1609 LOAD .S 2DROP DROP") == "<3> 1 3 5 "


# ---- MEMORY -----------------------------------------------------------------------
def test_memory_allocate_free_resize(forth):
    # the first ALLOCATE takes the 4096-byte heap from the top of the dictionary space
    forth.send("VARIABLE A1  VARIABLE A2  VARIABLE A3  0 VALUE BEFORE  0 VALUE HERE0")
    forth.send("UNUSED TO BEFORE  HERE TO HERE0")
    assert forth.send("100 ALLOCATE . A1 ! HERE HERE0 = . BEFORE UNUSED - .") == "0 -1 4096 "
    assert forth.send("A1 @ 1 AND . 1000 ALLOCATE . A2 ! 2000 ALLOCATE . A3 !") == "0 0 0 "
    assert forth.send("1000 ALLOCATE NIP .") == "-59 "  # 4096 - 102 - 1002 - 2002 left
    # freed neighbours join again: after FREE of the first two, 1100 bytes fit there
    assert forth.send("A1 @ FREE . A2 @ FREE . 1100 ALLOCATE . A1 @ = .") == "0 0 0 -1 "
    assert forth.send("A1 @ FREE . A1 @ FREE . HERE FREE .") == "0 -60 -60 "
    # RESIZE keeps the data: in place when the space after it is free, else moved
    forth.send("S\" kept\" A3 @ SWAP MOVE")
    assert forth.send("A3 @ 10 RESIZE . A3 @ = .") == "0 -1 "
    assert forth.send("1200 ALLOCATE . A2 !  A3 @ 500 RESIZE . DUP A3 @ <> . DUP A3 ! 4 TYPE") \
        == "0 0 -1 kept"
    assert forth.send("A3 @ -1 RESIZE . A3 @ = . -1 ALLOCATE NIP .") == "-61 -1 -59 "
    assert forth.send("A3 @ FREE . A2 @ FREE . 4000 ALLOCATE . FREE .") == "0 0 0 0 "


# ---- LOCALS -----------------------------------------------------------------------
def test_locals(forth):
    forth.send(": L1 {: a b | c -- sum :} a b + TO c  c c * ;")
    assert forth.send("3 4 L1 .") == "49 "
    forth.send(": L2 {: n :} n 0> IF n 1- RECURSE n + EXIT THEN 0 ;")  # EXIT drops the frame
    assert forth.send("10 L2 . DEPTH .") == "55 0 "
    forth.send(": L3 {: I :} 3 0 DO I LOOP ;")  # a local named I hides the loop's I
    assert forth.send("7 L3 .S 2DROP DROP") == "<3> 7 7 7 "
    forth.send(": L4 {: x :} CREATE x , DOES> @ {: y :} y 2* ;")
    assert forth.send("21 L4 FORTY-TWO  FORTY-TWO .") == "42 "
    forth.send(": LOCAL BL WORD COUNT (LOCAL) ; IMMEDIATE  : END-LOCALS 0 0 (LOCAL) ; IMMEDIATE")
    forth.send(": L5 LOCAL p LOCAL q END-LOCALS p q - ;")  # (LOCAL): the first is the top
    assert forth.send("10 3 L5 .") == "-7 "
    assert "L1" in forth.send("SEE L1") and "(LOCAL@) 0" in forth.send("SEE L1")
    # an error inside a definition with locals leaves no name behind
    assert "undefined word: nosuch" in forth.reply(": L6 {: z :} z nosuch ;").error
    assert "undefined word: z" in forth.reply("z").error
    assert forth.send(": L7 {: z :} z 1+ ; 1 L7 .") == "2 "
    assert forth.send('S" #LOCALS" ENVIRONMENT? . .') == "-1 16 "


def test_locals_names_room(forth):
    """The locals' names live in LOCALS-AREA, 236 bytes outside the dictionary
    (forth/kernel/memory.fs; issue 19 gave their old dictionary bytes to the hash
    chains): 16 locals of short names fit, more than the room is a clear error
    and the dictionary stays as it was."""
    names = " ".join(f"a{k}" for k in range(1, 17))
    forth.send(f": L8 {{: {names} :}} a1 a16 - a8 + ;")
    assert forth.send(" ".join(str(k) for k in range(1, 17)) + " L8 .") == "-7 "
    long = " ".join(f"{chr(97 + k)}{'x' * 30}" for k in range(7))  # 7 x 38 bytes
    here = forth.send("HERE U.")
    assert "local names too long" in forth.reply(f": L9 {{: {long} :}} ;").error
    assert forth.send("HERE U.") == here and forth.reply("L9").error == "undefined word: L9"
    assert forth.send("1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 L8 .") == "-7 "
