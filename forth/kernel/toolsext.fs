\ forth/kernel/toolsext.fs: TOOLS EXT words (Forth-2012 15.6.2) beyond CODE
\ ;CODE ASSEMBLER EDITOR FORGET (code.fs, editor.fs, tools.fs).

: AHEAD  ( -- orig )  ['] BRANCH , >MARK ;  IMMEDIATE COMPILE-ONLY  \ TOOLS EXT
\ a control-flow item is two cells (address, tag): CS-PICK and CS-ROLL move pairs
: CS-PICK  ( C: x_u .. x_0 -- x_u .. x_0 x_u ) ( u -- )  2* 2+ DUP PICK SWAP 1- PICK ;  \ TOOLS EXT
: CS-ROLL  ( C: x_u .. x_0 -- x_u-1 .. x_0 x_u ) ( u -- )  2* 1+ DUP >R ROLL R> ROLL ;  \ TOOLS EXT
CODE N>R  ( i*x n -- ) ( R: -- i*x n )  \ TOOLS EXT
  R0 S )+ MOV,  T R0 MOV,
  NE IF,  BEGIN,  RP -) S )+ MOV,  T DEC,  EQ UNTIL,  THEN,
  RP -) R0 MOV,  NEXT,  END-CODE  COMPILE-ONLY
CODE NR>  ( -- i*x n ) ( R: i*x n -- )  \ TOOLS EXT
  R0 RP )+ MOV,  T R0 MOV,
  NE IF,  BEGIN,  S -) RP )+ MOV,  T DEC,  EQ UNTIL,  THEN,
  S -) R0 MOV,  NEXT,  END-CODE  COMPILE-ONLY

\ ---- conditional compilation ------------------------------------------------------
: NAME=  ( a1 u1 a2 u2 -- f )  \ the same name, case ignored
  ROT OVER <> IF DROP 2DROP FALSE EXIT THEN
  0 ?DO OVER I + C@ UPC OVER I + C@ UPC <> IF 2DROP FALSE UNLOOP EXIT THEN LOOP
  2DROP TRUE ;
: [ELSE]  ( -- )  \ TOOLS EXT: skip to the matching [THEN], over lines and blocks
  1 BEGIN
    BEGIN PARSE-NAME DUP WHILE
      2DUP S" [IF]" NAME= IF 2DROP 1+ ELSE
      2DUP S" [ELSE]" NAME= IF 2DROP 1- DUP IF 1+ THEN ELSE
      S" [THEN]" NAME= IF 1- THEN THEN THEN
      ?DUP 0= IF EXIT THEN
    REPEAT 2DROP
  REFILL 0= UNTIL DROP ;  IMMEDIATE
: [IF]  ( f -- )  0= IF POSTPONE [ELSE] THEN ;  IMMEDIATE  \ TOOLS EXT
: [THEN]  ( -- )  ;  IMMEDIATE  \ TOOLS EXT
: [DEFINED]  ( "name" -- f )  PARSE-NAME SEARCH-NAME 0<> ;  IMMEDIATE  \ TOOLS EXT
: [UNDEFINED]  ( "name" -- f )  PARSE-NAME SEARCH-NAME 0= ;  IMMEDIATE  \ TOOLS EXT

\ ---- name tokens: a name token (nt) is the name field address -----------------------
: NAME>STRING  ( nt -- a u )  COUNT 31 AND ;  \ TOOLS EXT
: NAME>INTERPRET  ( nt -- xt )  NAME> ;  \ TOOLS EXT
: NAME>COMPILE  ( nt -- x xt )  \ TOOLS EXT
  DUP NAME> SWAP C@ 128 AND IF ['] EXECUTE ELSE ['] COMPILE, THEN ;
: TRAVERSE-CHAIN  ( i*x xt lfa -- j*x xt f )  \ f false: xt asked to stop
  BEGIN ?DUP WHILE
    DUP 2+ C@ 32 AND 0= IF  \ a smudged (unfinished) word is not shown
      2>R 2R@ 2+ SWAP EXECUTE 2R> ROT 0= IF DROP FALSE EXIT THEN
    THEN @
  REPEAT TRUE ;
: TRAVERSE-WORDLIST  ( i*x xt wid -- j*x )  \ TOOLS EXT: xt ( nt -- f ) per word
  DUP CHAIN-BYTES + SWAP DO  I @ TRAVERSE-CHAIN 0= IF DROP UNLOOP EXIT THEN  2 +LOOP DROP ;
: SYNONYM  ( "newname" "oldname" -- )  \ TOOLS EXT: code field JMP @#old
  ?END-CODE  PARSE-NAME PARSE-NAME ?NAME >R  HEADER,  JMP-ABS ,  R@ NAME> ,
  R> C@ 192 AND  LAST @ DUP C@ ROT OR SWAP C! ;

\ ---- BYE: the simulator stops at (BYE)'s HALT; the console harness sees it there
\ and leaves as when BYE is typed (CONT, FLUSH, detach, quit: harness/machine/console_session.py)
CODE (BYE)  ( -- )  HALT,  NEXT,  END-CODE  \ CONT at sim> goes on after the HALT
: BYE  ( -- )  FLUSH  (BYE) ;  \ TOOLS EXT
