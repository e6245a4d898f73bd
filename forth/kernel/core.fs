\ forth/kernel/core.fs: high-level CORE words built on the primitives.

\ ---- constants and system variables ------------------------------------------
-1 CONSTANT TRUE  ( -- -1 )  \ CORE EXT
0 CONSTANT FALSE  ( -- 0 )  \ CORE EXT
32 CONSTANT BL  ( -- c )  \ CORE
S0 CONSTANT S0  ( -- a ) \ empty data stack
RP0 CONSTANT RP0  ( -- a ) \ empty return stack
LIMIT CONSTANT LIMIT  ( -- a ) \ end of the dictionary space
LIMIT VAR DICT-END  ( -- a ) \ the dictionary ends here: LIMIT, or the heap's start (heap.fs)
BUFFERS CONSTANT BUFFERS  ( -- a ) \ block buffer area (disk.fs)
BUFFERS-SIZE CONSTANT BUFFERS-SIZE  ( -- n )
TIB0 CONSTANT TIB  ( -- a )  \ CORE EXT
RXLOST CONSTANT RXLOST  ( -- a ) \ console characters lost to a full ring
RXDROP CONSTANT RXDROP  ( -- a ) \ typed-ahead characters ^C dropped
VARIABLE STATE  ( -- a ) \ CORE: true while compiling
10 VAR BASE  ( -- a )  \ CORE
VARIABLE DP  ( -- a ) \ HERE; set by the metacompiler
VARIABLE LAST  ( -- a ) \ name field of the newest word
8 ARRAY CONTEXT  ( -- a ) \ the search order: wid searched first, then the rest
VARIABLE #ORDER  ( -- a ) \ wordlists in the search order (CONTEXT's cells in use)
VARIABLE CURRENT  ( -- a ) \ vocabulary new words go into
VARIABLE VOC-LINK  ( -- a ) \ newest vocabulary's link cell
VARIABLE FENCE  ( -- a ) \ FORGET stops here (end of the kernel)
VARIABLE HANDLER  ( -- a ) \ innermost CATCH frame
VARIABLE >IN  ( -- a )  \ CORE
VARIABLE BLK  ( -- a ) \ BLOCK: block being interpreted, 0 = none
VARIABLE #TIB  ( -- a )  \ CORE EXT
VARIABLE SRC-ID  ( -- a ) \ SOURCE-ID's value: 0 terminal (or block), -1 EVALUATE
2 ARRAY SRC  ( -- a ) \ address and length of the current text source
VARIABLE HLD  ( -- a ) \ pictured numeric output pointer
VARIABLE WARNING  ( -- a )

\ ---- stack, arithmetic ---------------------------------------------------------
: -ROT  ( a b c -- c a b )  ROT ROT ;
: ABS  ( n -- u )  DUP 0< IF NEGATE THEN ;  \ CORE
: MIN  ( a b -- min )  2DUP > IF SWAP THEN DROP ;  \ CORE
: MAX  ( a b -- max )  2DUP < IF SWAP THEN DROP ;  \ CORE
: S>D  ( n -- d )  DUP 0< ;  \ CORE
: DABS  ( d -- ud )  DUP 0< IF DNEGATE THEN ;  \ DOUBLE
: ?NEGATE  ( n f -- n' )  0< IF NEGATE THEN ;
: FM/MOD  ( d n -- rem quot )  \ CORE: floored: adjust the symmetric result
  DUP >R SM/REM  OVER 0<> IF OVER R@ XOR 0< IF 1- SWAP R@ + SWAP THEN THEN
  R> DROP ;
: /MOD  ( a b -- rem quot )  >R S>D R> SM/REM ;  \ CORE
: /  ( a b -- quot )  /MOD NIP ;  \ CORE
: MOD  ( a b -- rem )  /MOD DROP ;  \ CORE
: */MOD  ( a b c -- rem quot )  >R M* R> SM/REM ;  \ CORE
: */  ( a b c -- quot )  */MOD NIP ;  \ CORE
: ROLL  ( xu .. x0 u -- xu-1 .. x0 xu )  \ CORE EXT: u beyond the stack: error -4
  DUP DEPTH 2 - U< 0= IF -4 THROW THEN
  DUP 1+ PICK >R  SP@ 2+ DUP 2+ ROT 2* CMOVE>  DROP R> ;
: WITHIN  ( x lo hi -- f )  OVER - >R - R> U< ;  \ CORE EXT
: CELL+  ( a -- a+2 )  2+ ;  \ CORE
: CELLS  ( n -- 2n )  2* ;  \ CORE
: CHAR+  ( a -- a+1 )  1+ ;  \ CORE
: CHARS  ( n -- n )  ;  \ CORE
: ALIGNED  ( a -- a' )  DUP 1 AND + ;  \ CORE
: COUNT  ( ca -- a u )  DUP 1+ SWAP C@ ;  \ CORE
: MOVE  ( src dst u -- )  >R 2DUP U< IF R> CMOVE> ELSE R> CMOVE THEN ;  \ CORE
: ERASE  ( a u -- )  0 FILL ;  \ CORE EXT
: COMPARE  ( a1 u1 a2 u2 -- -1|0|1 )  \ STRING: byte values, then lengths
  ROT 2DUP - >R MIN 0 ?DO
    OVER I + C@ OVER I + C@ - ?DUP IF 0< 2* 1+ NIP NIP UNLOOP R> DROP EXIT THEN
  LOOP 2DROP R> DUP IF 0< 2* 1+ NEGATE THEN ;

\ ---- errors: CATCH and THROW (Forth-2012 exception words) -------------------------
: SOURCE-ID  ( -- 0 | -1 )  SRC-ID @ ;  \ CORE EXT: 0 user input device, -1 EVALUATE
\ A CATCH frame also holds the input source, which THROW restores (Forth-2012
\ 9.6.1.2275): a word that fails inside EVALUATE or LOAD leaves the caller's
\ source in place. ERR-BLK and ERR-IN keep where the error happened, for .ERROR.
VARIABLE ERR-BLK  ( -- a ) \ BLK when the last THROW happened
VARIABLE ERR-IN  ( -- a ) \ >IN then
: CATCH  ( i*x xt -- j*x 0 | i*x code )  \ EXCEPTION
  DEPTH 1 < IF -4 THROW THEN  SRC 2@ >R >R  >IN @ >R  BLK @ >R  SRC-ID @ >R
  SP@ >R  HANDLER @ >R  RP@ HANDLER !  EXECUTE  R> HANDLER !
  RP@ 12 + RP!  0 ;  \ drop the saved SP and the saved source
: THROW  ( k*x code -- k*x | i*x code )  \ EXCEPTION
  ?DUP IF
    DUP -256 = IF DISARM 0 PRIORITY! TRAP-CODE THEN  \ a trap arrives at priority 7
    BLK @ ERR-BLK !  >IN @ ERR-IN !
    HANDLER @ RP@ RP0 WITHIN 0= IF 0 HANDLER ! THEN  \ a frame below RP is stale
    HANDLER @ 0= IF RP0 RP! ABORT-TO-QUIT THEN  \ (: X R> DROP ; ' X CATCH left
    \ it); no CATCH frame: nothing on the return stack is needed, however broken
    HANDLER @ RP!  R> HANDLER !  R> SWAP >R SP! DROP R>
    R> SRC-ID !  R> BLK !  R> >IN !  R> R> SRC 2! THEN ;
VARIABLE ABORT-MSG  ( -- a ) \ counted message of the last ABORT"
: ABORT  ( -- )  -1 THROW ;  \ CORE, EXCEPTION EXT
: (ABORT")  ( f -- )  R> COUNT 2DUP + ALIGNED >R ROT IF DROP 1- ABORT-MSG ! -2 THROW THEN 2DROP ;
  COMPILE-ONLY

\ ---- the dictionary ----------------------------------------------------------------
: HERE  ( -- a )  DP @ ;  \ CORE
: UNUSED  ( -- n )  DICT-END @ HERE - 160 - ;  \ CORE EXT
: ALLOT  ( n -- )  \ CORE: n signed; nothing allotted on an error
  DUP 0< IF DUP NEGATE HERE FENCE @ - U> IF -9 THROW THEN  \ never below the kernel
    DP +!  HERE LAST @ NAME> 4 + U< IF  \ into the newest header: that word and
      LAST @ 2- HERE 2DUP U< IF SWAP THEN DROP (FORGET)  \ any above HERE are
    THEN EXIT                                           \ forgotten, as by FORGET
  THEN  DUP UNUSED U> IF -8 THROW THEN  DP +! ;
: ,  ( x -- )  HERE 2 ALLOT ! ;  \ CORE
: C,  ( c -- )  HERE 1 ALLOT C! ;  \ CORE
: ALIGN  ( -- )  HERE 1 AND ALLOT ;  \ CORE
: PAD  ( -- a )  HERE 68 + ;  \ CORE EXT: 92 bytes up to UNUSED's reserve; the pictured buffer below it
: NAME>  ( nfa -- xt )  DUP C@ 31 AND + 1+ ALIGNED ;
: >BODY  ( xt -- a )  4 + ;  \ CORE

\ ---- console output ----------------------------------------------------------------
: CR  ( -- )  13 EMIT 10 EMIT ;  \ CORE
: SPACE  ( -- )  BL EMIT ;  \ CORE
: SPACES  ( n -- )  BEGIN DUP 0> WHILE SPACE 1- REPEAT DROP ;  \ CORE
: TYPE  ( a u -- )  0 ?DO DUP C@ EMIT 1+ LOOP DROP ;  \ CORE
: (.")  ( -- )  R> COUNT 2DUP + ALIGNED >R TYPE ;  COMPILE-ONLY
: (S")  ( -- a u )  R> COUNT 2DUP + ALIGNED >R ;  COMPILE-ONLY

\ ---- pictured numeric output -------------------------------------------------------
: <#  ( -- )  PAD HLD ! ;  \ CORE
: HOLD  ( c -- )  \ CORE: the buffer runs from PAD down to HERE: error -17 when full
  HLD @ 1- DUP HERE PAD WITHIN 0= IF -17 THROW THEN  DUP HLD ! C! ;
: DIGIT  ( n -- c )  DUP 9 > IF 7 + THEN [CHAR] 0 + ;
: UD/MOD  ( ud u -- rem ud' )  >R 0 R@ UM/MOD R> SWAP >R UM/MOD R> ;
: ?BASE  ( -- )  \ BASE outside 2..36 would print nothing sensible (1: for ever)
  BASE @ 2 37 WITHIN 0= IF -24 THROW THEN ;
: #  ( ud -- ud' )  ?BASE BASE @ UD/MOD ROT DIGIT HOLD ;  \ CORE
: #S  ( ud -- 0 0 )  BEGIN # 2DUP OR 0= UNTIL ;  \ CORE
: #>  ( ud -- a u )  2DROP HLD @ PAD OVER - ;  \ CORE
: SIGN  ( n -- )  0< IF [CHAR] - HOLD THEN ;  \ CORE
: D.R  ( d n -- )  \ DOUBLE: every number printer ends here: none prints from an
  DEPTH 3 < IF -4 THROW THEN  \ empty stack
  >R TUCK DABS <# #S ROT SIGN #> R> OVER - SPACES TYPE ;
: D.  ( d -- )  0 D.R SPACE ;  \ DOUBLE
: .  ( n -- )  S>D D. ;  \ CORE
: U.  ( u -- )  0 D. ;  \ CORE
: .R  ( n width -- )  >R S>D R> D.R ;  \ CORE EXT
: U.R  ( u width -- )  0 SWAP D.R ;  \ CORE EXT
: DECIMAL  ( -- )  10 BASE ! ;  \ CORE
: HEX  ( -- )  16 BASE ! ;  \ CORE EXT
: OCTAL  ( -- )  8 BASE ! ;
: ?  ( a -- )  @ . ;  \ TOOLS

\ ---- console input: echo, backspace/delete, ^U, tab = blank; CR or LF ends a line
VARIABLE LAST-CR  ( -- a ) \ the previous line ended with CR (skip its LF)
: BACKUP  ( -- )  8 EMIT SPACE 8 EMIT ;
: ACCEPT  ( a n -- n' )  \ CORE
  >R 0  BEGIN KEY
    DUP 10 = LAST-CR @ AND IF DROP KEY THEN  0 LAST-CR !
    DUP 9 = IF DROP BL THEN  \ a tab is a blank
    DUP 13 <> OVER 10 <> AND WHILE
    DUP 8 = OVER 127 = OR IF DROP DUP IF 1- BACKUP THEN
    ELSE DUP 21 = IF DROP BEGIN DUP WHILE 1- BACKUP REPEAT
    ELSE DUP BL < IF DROP
    ELSE OVER R@ < IF DUP EMIT >R 2DUP + R> SWAP C! 1+ ELSE DROP 7 EMIT THEN
    THEN THEN THEN
  REPEAT 13 = LAST-CR !  R> DROP NIP ;
