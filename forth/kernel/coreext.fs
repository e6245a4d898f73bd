\ forth/kernel/coreext.fs: the CORE EXT words interp.fs and core.fs do not
\ define already (Forth-2012 6.2), and the input-source words.

CODE 2R@  ( -- x1 x2 ) ( R: x1 x2 -- x1 x2 )  \ CORE EXT
  S -) 2 RP I) MOV,  S -) RP ) MOV,  NEXT,  END-CODE  COMPILE-ONLY
: BUFFER:  ( u "name" -- )  CREATE ALLOT ;  \ CORE EXT: name gives u bytes
: HOLDS  ( a u -- )  \ CORE EXT: the string, in the pictured output
  BEGIN DUP WHILE 1- 2DUP + C@ HOLD REPEAT 2DROP ;
: (C")  ( -- ca )  R> DUP COUNT + ALIGNED >R ;  COMPILE-ONLY
: C"  ( "ccc<quote>" -- )  ['] (C") , ," ;  IMMEDIATE COMPILE-ONLY  \ CORE EXT

\ ---- CASE OF ENDOF ENDCASE: every ENDOF leaves an orig; CASE's mark (tag 6) ends them
: CASE  ( -- case-sys )  0 6 ;  IMMEDIATE COMPILE-ONLY  \ CORE EXT
: OF  ( -- of-sys )  \ CORE EXT
  POSTPONE OVER POSTPONE = POSTPONE IF POSTPONE DROP ;  IMMEDIATE COMPILE-ONLY
: ENDOF  ( of-sys -- orig )  POSTPONE ELSE ;  IMMEDIATE COMPILE-ONLY  \ CORE EXT
: ENDCASE  ( case-sys orig* -- )  \ CORE EXT
  POSTPONE DROP  BEGIN DUP 1 = WHILE POSTPONE THEN REPEAT  6 ?PAIRS DROP ;
  IMMEDIATE COMPILE-ONLY

\ ---- DEFER IS ACTION-OF, VALUE TO ------------------------------------------------
: NO-ACTION  ( -- )  -21 THROW ;  \ a DEFER not yet given an action
: DEFER  ( "name" -- )  CREATE ['] NO-ACTION ,  DOES> @ EXECUTE ;  \ CORE EXT
: DEFER@  ( xt1 -- xt2 )  >BODY @ ;  \ CORE EXT
: DEFER!  ( xt2 xt1 -- )  >BODY ! ;  \ CORE EXT
137O CONSTANT JMP-ABS  ( -- op ) \ JMP @#a: a SYNONYM's code field (toolsext.fs)
: SYNONYM>  ( xt -- xt' )  \ through SYNONYMs to the word itself
  BEGIN DUP @ JMP-ABS = WHILE 2+ @ REPEAT ;
: TICK-DOES  ( i*x xt "name" -- j*x )  \ xt on name's xt now, or compiled that way
  TICK SYNONYM> STATE @ IF POSTPONE LITERAL COMPILE, ELSE SWAP EXECUTE THEN ;
: IS  ( xt "name" -- )  ['] DEFER! TICK-DOES ;  IMMEDIATE  \ CORE EXT
: ACTION-OF  ( "name" -- xt )  ['] DEFER@ TICK-DOES ;  IMMEDIATE  \ CORE EXT
: VALUE!  ( x | x1 x2 xt -- )  \ a VALUE is a constant, a 2VALUE a DOES> child
  DUP 2+ @ 'DOCON = IF >BODY ! ELSE >BODY 2! THEN ;
: TO  ( x "name" -- )  \ CORE EXT, DOUBLE EXT, LOCALS
  >IN @ PARSE-NAME LOCAL-TO? IF DROP EXIT THEN  >IN !  ['] VALUE! TICK-DOES ;  IMMEDIATE

\ ---- the input source: S\" REFILL SAVE-INPUT RESTORE-INPUT -------------------------
: SOURCE!  ( a u -- )  SRC 2!  0 >IN ! ;
: REFILL  ( -- f )  \ CORE EXT, BLOCK EXT: the next line, or the next block
  SOURCE-ID IF FALSE EXIT THEN
  BLK @ IF 1 BLK +!  0 >IN !  BLK @ #BLOCKS U< EXIT THEN
  QUERY TRUE ;
: SAVE-INPUT  ( -- x1 .. x5 5 )  \ CORE EXT
  SRC 2@ >IN @ BLK @ SOURCE-ID 5 ;
: RESTORE-INPUT  ( x1 .. xn n -- f )  \ CORE EXT: f false when restored
  DUP 5 <> IF DEPTH 1- MIN 0 MAX 0 ?DO DROP LOOP TRUE EXIT THEN DROP  \ not ours
  SRC-ID ! BLK ! >IN ! SRC 2! FALSE ;
: ESCAPE  ( c -- c' )  \ the character \c stands for in S\" (\m \n \x: ESC-PARSE)
  DUP [CHAR] a = IF DROP 7 EXIT THEN   DUP [CHAR] b = IF DROP 8 EXIT THEN
  DUP [CHAR] e = IF DROP 27 EXIT THEN  DUP [CHAR] f = IF DROP 12 EXIT THEN
  DUP [CHAR] l = IF DROP 10 EXIT THEN
  DUP [CHAR] q = IF DROP 34 EXIT THEN  DUP [CHAR] r = IF DROP 13 EXIT THEN
  DUP [CHAR] t = IF DROP 9 EXIT THEN   DUP [CHAR] v = IF DROP 11 EXIT THEN
  DUP [CHAR] z = IF DROP 0 EXIT THEN ;
: NEXT-CHAR  ( -- c )  REST IF C@ ELSE DROP 0 THEN  1 >IN +! ;
: HEX-DIGIT  ( -- n )  NEXT-CHAR BASE @ >R HEX DIGIT? 0= IF 0 THEN R> BASE ! ;
: ESC-PARSE  ( a -- u )  \ S\" text up to the closing quote, escapes translated, to a
  DUP BEGIN
    REST NIP 0= IF SWAP - EXIT THEN  NEXT-CHAR
    DUP [CHAR] " = IF DROP SWAP - EXIT THEN
    DUP [CHAR] \ = IF DROP NEXT-CHAR
      DUP [CHAR] m = OVER [CHAR] n = OR IF DROP 13 OVER C! 1+ 10 ELSE  \ CR LF
      DUP [CHAR] x = IF DROP HEX-DIGIT 16 * HEX-DIGIT + ELSE ESCAPE THEN THEN
    THEN OVER C! 1+
  AGAIN ;
: S\"  ( "ccc<quote>" -- a u )  \ CORE EXT, FILE EXT
  STATE @ IF ['] (S") ,  HERE 1+ ESC-PARSE DUP C, ALLOT ALIGN EXIT THEN
  HERE DUP ESC-PARSE SBUF-COPY ;  IMMEDIATE  \ as S": one of its buffers
