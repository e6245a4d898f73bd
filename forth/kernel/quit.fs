\ forth/kernel/quit.fs: the outer interpreter, EVALUATE, error reports, QUIT.

S-LIMIT CONSTANT S-LIMIT  ( -- a )
2 ARRAY WHAT  ( -- a ) \ the word being interpreted: address, length
VARIABLE 'ON-ERROR  ( -- a ) \ xt run after every error (0 = none)
: ?STACK  ( -- )
  SP@ S0 U> IF -4 THROW THEN  SP@ S-LIMIT 16 + U< IF -3 THROW THEN ;
\ Control structures typed at the terminal (0 3 DO I . -1 +LOOP): an opening
\ IF BEGIN DO ?DO in interpret state starts a temporary definition at HERE;
\ when the structure closes it is run and HERE is put back.
VARIABLE TEMP-DEPTH  ( -- a ) \ depth+1 when it started, 0 = none
VARIABLE TEMP-START  ( -- a ) \ where its code starts (HERE aligned)
VARIABLE TEMP-HERE  ( -- a ) \ HERE before it, put back afterwards
: OPENER?  ( xt -- xt f )
  DUP ['] IF = OVER ['] BEGIN = OR OVER ['] DO = OR OVER ['] ?DO = OR ;
: TEMP-BEGIN  ( xt -- xt )  \ xt is still on the stack: DEPTH counts it (the +1)
  HERE TEMP-HERE !  ALIGN HERE TEMP-START !  'DOCOL JSR-IP CF,  DEPTH TEMP-DEPTH !  ] ;
: TEMP-END?  ( -- )  \ structure closed: run it, forget it
  TEMP-DEPTH @ IF DEPTH 1+ TEMP-DEPTH @ = IF
    ['] EXIT ,  POSTPONE [  0 TEMP-DEPTH !  TEMP-HERE @ DP !  TEMP-START @ EXECUTE
  THEN THEN ;
: INTERPRET  ( -- )
  BEGIN PARSE-NAME DUP WHILE
    2DUP WHAT 2!  2DUP SEARCH-NAME ?DUP IF
      NIP NIP DUP NAME> SWAP C@
      STATE @ IF 128 AND IF EXECUTE ELSE , THEN
      ELSE 64 AND IF OPENER? 0= IF -14 THROW THEN TEMP-BEGIN THEN EXECUTE THEN
    ELSE NUMBER THEN
    ?STACK TEMP-END?
  REPEAT 2DROP ;
: EVALUATE  ( a u -- )  \ CORE, BLOCK
  SRC 2@ 2>R  >IN @ >R  BLK @ >R  SRC-ID @ >R
  SRC 2!  0 >IN !  0 BLK !  -1 SRC-ID !  INTERPRET
  R> SRC-ID !  R> BLK !  R> >IN !  2R> SRC 2! ;

\ ---- reverse lookup: which word holds an address -----------------------------------
VARIABLE BEST  ( -- a )
: BEST-IN  ( addr lfa -- addr )  \ one chain: keep the best header in BEST
  BEGIN ?DUP WHILE
    DUP 2+ NAME> 2 PICK SWAP U< 0= IF
      DUP 2+ NAME> BEST @ ?DUP IF NAME> U> ELSE DROP TRUE THEN
      IF DUP 2+ BEST ! THEN
    THEN @
  REPEAT ;
: WORD-AT  ( addr -- nfa | 0 )  \ the word whose code or body holds addr
  0 BEST !  VOC-LINK @ BEGIN ?DUP WHILE
    4 0 DO DUP 8 - I 2* + @ ROT SWAP BEST-IN SWAP LOOP @
  REPEAT DROP BEST @ ;
: >NAME  ( xt -- nfa | 0 )  DUP WORD-AT DUP IF TUCK NAME> <> IF DROP 0 THEN ELSE NIP THEN ;
: .NAME  ( nfa -- )  COUNT 31 AND TYPE ;
: .OCTAL  ( u -- )  BASE @ >R 8 BASE ! 0 <# # # # # # # #> TYPE R> BASE ! ;

\ ---- error reports -------------------------------------------------------------
VARIABLE DISARMED  ( -- a ) \ vector DISARM put back, -1 = none
: DISARM  ( -- )  \ an interrupt handler that trapped leaves its vector
  -1 DISARMED !  TRAP-PC @ WORD-AT ?DUP 0= IF EXIT THEN
  1000O 0 DO
    I @ WORD-AT OVER = IF STUBS I + I !  I DISARMED ! THEN
  4 +LOOP DROP ;
: .DISARMED  ( -- )
  DISARMED @ DUP 0< IF DROP EXIT THEN
  ." ; vector " .OCTAL ."  restored to its default handler"  -1 DISARMED ! ;
: .TRAP  ( -- )  \ what the last unexpected trap was, and where
  TRAP-VEC @ DUP 4 = IF ." bus error or odd address" ELSE
    DUP 10O = IF ." illegal or reserved instruction" ELSE
    DUP 14O = IF ." breakpoint trap (BPT)" ELSE
    DUP 20O = IF ." IOT trap" ELSE
    DUP 30O = IF ." EMT trap" ELSE
    DUP 34O = IF ." TRAP instruction" ELSE
    DUP 24O = IF ." power fail" ELSE
    ." unexpected interrupt" THEN THEN THEN THEN THEN THEN THEN
  ."  (vector " .OCTAL ." , PC " TRAP-PC @ DUP .OCTAL
  WORD-AT ?DUP IF ."  in " .NAME THEN  .DISARMED ." )" ;
: .ERROR-TEXT  ( code -- )
  DUP -1 = IF DROP ." aborted" EXIT THEN
  DUP -2 = IF DROP ABORT-MSG @ COUNT TYPE EXIT THEN
  DUP -3 = IF DROP ." stack overflow" EXIT THEN
  DUP -4 = IF DROP ." stack underflow" EXIT THEN
  DUP -5 = IF DROP ." return stack overflow" EXIT THEN
  DUP -8 = IF DROP ." dictionary full" EXIT THEN
  DUP -9 = IF DROP ." invalid memory address" EXIT THEN
  DUP -10 = IF DROP ." division by zero" EXIT THEN
  DUP -13 = IF DROP ." undefined word" EXIT THEN
  DUP -14 = IF DROP ." compile-only word interpreted" EXIT THEN
  DUP -15 = IF DROP ." cannot forget kernel words" EXIT THEN
  DUP -16 = IF DROP ." name expected" EXIT THEN
  DUP -19 = IF DROP ." name longer than 31 characters" EXIT THEN
  DUP -21 = IF DROP ." unsupported operation (a DEFER without an action?)" EXIT THEN
  DUP -22 = IF DROP ." unbalanced control structure" EXIT THEN
  DUP -23 = IF DROP ." odd address for a word access" EXIT THEN
  DUP -28 = IF DROP ." interrupted by ^C" EXIT THEN
  DUP -33 = IF DROP ." block read error" EXIT THEN
  DUP -34 = IF DROP ." block write error" EXIT THEN
  DUP -35 = IF DROP ." no such block" EXIT THEN
  DUP -49 = IF DROP ." search-order overflow" EXIT THEN
  DUP -50 = IF DROP ." search-order underflow" EXIT THEN
  DUP -256 = IF DROP .TRAP EXIT THEN
  ." error " . ;
\ An undefined word that a vocabulary outside the search order holds (after an
\ error the context is CURRENT again, so the editor's P is gone until EDITOR is
\ typed): say which vocabulary to type.
: IN-ORDER?  ( wid -- f )  \ is wid in the search order?
  FALSE #ORDER @ 2* CONTEXT + CONTEXT ?DO OVER I @ = OR 2 +LOOP NIP ;
: .ELSEWHERE  ( -- )
  VOC-LINK @ BEGIN ?DUP WHILE
    DUP 8 -  DUP VOC-NAME OVER IN-ORDER? 0= AND IF
      WHAT 2@ 2 PICK WID-FIND IF
        ."  (a word of " DUP VOC-NAME .NAME ." : type " VOC-NAME .NAME
        ."  to select it again)" DROP EXIT
      THEN
    THEN DROP @
  REPEAT ;
: .ERROR  ( code -- )  \ Error: what: word [in block b line l] [(where it is)]
  CR ." Error: " DUP .ERROR-TEXT  ." : " WHAT 2@ TYPE
  ERR-BLK @ IF ."  in block " ERR-BLK @ . ." line " ERR-IN @ 1- 0 MAX 64 / . THEN
  -13 = IF .ELSEWHERE THEN CR ;
: UNLINK  ( lfa -- )  \ the newest header of CURRENT leaves, HERE goes back to it
  DUP @ OVER 2+ C@ CURRENT @ SWAP CHAIN !  DP !  CURRENT @ NEWEST 2+ LAST ! ;
: DISCARD-DEFINITION  ( -- )  \ a definition cut short leaves nothing behind
  STATE @ IF COLON-LFA @ ?DUP IF UNLINK THEN THEN
  0 COLON-LFA !  TEMP-DEPTH @ IF TEMP-HERE @ DP !  0 TEMP-DEPTH ! THEN ;
: CONTEXT-AFTER-ERROR  ( -- )  \ FORTH-79: CONTEXT := CURRENT; an empty order: the boot one
  #ORDER @ 0= IF ONLY ALSO THEN  CURRENT @ CONTEXT ! ;
: RESET-AFTER-ERROR  ( -- )
  DISCARD-DEFINITION  POSTPONE [  0 BLK !  0 SRC-ID !  CONTEXT-AFTER-ERROR
  'ON-ERROR @ ?DUP IF EXECUTE THEN  S0 SP!  0 PRIORITY! ;

\ ---- QUIT --------------------------------------------------------------------------
: .LOST  ( -- )  \ say so when the console ring overflowed
  RXLOST @ ?DUP IF CR U. ." characters lost: typed too far ahead" CR  0 RXLOST ! THEN ;
: QUERY  ( -- )  \ CORE EXT: a line from the terminal becomes the source
  TIB TIB-SIZE 1- ACCEPT  TIB SWAP SRC 2!  0 >IN !  0 BLK !  0 SRC-ID !  SPACE .LOST ;
: INTERPRET-LINE  ( -- )  QUERY INTERPRET ;
: QUIT  ( -- )  \ CORE: read, interpret, report: forever
  RP0 RP!  0 HANDLER !  POSTPONE [  0 BLK !  0 PRIORITY!
  BEGIN
    ['] INTERPRET-LINE CATCH ?DUP IF .ERROR RESET-AFTER-ERROR ELSE ."  ok" CR THEN
  AGAIN ;
: WARM  ( -- )  S0 SP! QUIT ;  \ THROW with no CATCH frame comes here
