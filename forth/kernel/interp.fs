\ forth/kernel/interp.fs: text interpreter, compiler, vocabularies, errors, QUIT.

\ ---- the input source ---------------------------------------------------------
: SOURCE  ( -- a u )  BLK @ IF BLK @ (BLOCK) 1024 ELSE SRC 2@ THEN ;  \ (BLOCK): disk.fs
: REST  ( -- a u )  \ unparsed part of the source
  SOURCE >IN @ OVER MIN /STRING ;
: PARSE  ( c -- a u )
  >R REST OVER SWAP R> SCAN  ( a a' u' )  0<> 1 AND >R  OVER -  DUP R> + >IN +! ;
: PARSE-NAME  ( -- a u )
  REST BL SKIP DROP SOURCE DROP - >IN !  BL PARSE ;
: WORD  ( c -- ca )  \ counted string at HERE, a blank after it
  >R REST R@ SKIP DROP SOURCE DROP - >IN !  R> PARSE
  DUP HERE C! HERE 1+ SWAP CMOVE  BL HERE COUNT + C!  HERE ;
: CHAR  ( "c" -- c )  PARSE-NAME DROP C@ ;
: (  ( "text<paren>" -- )  [CHAR] ) PARSE 2DROP ;  IMMEDIATE
: \  ( "line" -- )  \ in a block: to the end of the 64-character line
  BLK @ IF >IN @ 63 + -64 AND >IN ! ELSE SOURCE NIP >IN ! THEN ;  IMMEDIATE
: .(  ( "text<paren>" -- )  [CHAR] ) PARSE TYPE ;  IMMEDIATE

\ ---- numbers: optional -, digits in BASE, or a trailing O for octal --------------
: DIGIT?  ( c -- n true | false )
  UPC DUP [CHAR] 9 > IF DUP [CHAR] A < IF DROP FALSE EXIT THEN 7 - THEN
  [CHAR] 0 - DUP BASE @ U< IF TRUE ELSE DROP FALSE THEN ;
: UD*  ( ud u -- ud' )  DUP >R UM* DROP SWAP R> UM* ROT + ;
: >NUMBER  ( ud a u -- ud' a' u' )
  BEGIN DUP WHILE OVER C@ DIGIT? WHILE
    >R 2SWAP BASE @ UD* R> 0 D+ 2SWAP 1 /STRING
  REPEAT THEN ;
: NUMBER?  ( a u -- n true | a u false )
  ?BASE 2DUP BASE @ >R
  DUP 1 > IF 2DUP + 1- C@ UPC [CHAR] O = IF 1- 8 BASE ! THEN THEN
  OVER C@ [CHAR] - = DUP >R IF 1 /STRING THEN
  DUP IF 0 0 2SWAP >NUMBER NIP ELSE 2DROP 0 0 1 THEN
  R> SWAP R> BASE !  ( a u lo hi neg rest )
  IF 2DROP DROP FALSE EXIT THEN
  NIP ?NEGATE NIP NIP TRUE ;

\ ---- finding words -----------------------------------------------------------------
\ A vocabulary's body: +0 +2 +4 +6 the newest LFA of each of its four chains
\ (names of length 0, 1, 2, 3 mod 4), +10 its VOC-LINK cell.
\ Search: CONTEXT, then FORTH, each in the chain of the name's length.
: CHAIN  ( voc u -- a )  3 AND 2* + ;
: SEARCH-NAME  ( a u -- nfa | 0 )
  CONTEXT @ FORTH-BODY <> IF
    2DUP CONTEXT @ OVER CHAIN @ (FIND) ?DUP IF NIP NIP EXIT THEN
  THEN  FORTH-BODY OVER CHAIN @ (FIND) ;
: UMAX  ( u1 u2 -- u )  2DUP U< IF SWAP THEN DROP ;
: NEWEST-SLOT  ( heads -- slot | 0 )  \ the cell holding the newest header
  0 SWAP 4 0 DO
    DUP @ IF OVER 0= IF NIP DUP ELSE OVER @ OVER @ U< IF NIP DUP THEN THEN THEN
    2+
  LOOP DROP ;
: NEWEST  ( voc -- lfa | 0 )  NEWEST-SLOT DUP IF @ THEN ;
: FIND  ( ca -- ca 0 | xt 1 | xt -1 )
  DUP COUNT SEARCH-NAME ?DUP IF NIP DUP NAME> SWAP C@ 128 AND IF 1 ELSE -1 THEN THEN ;
: TICK  ( "name" -- xt )  PARSE-NAME SEARCH-NAME ?DUP 0= IF -13 THROW THEN NAME> ;

\ ---- compiling ---------------------------------------------------------------------
\ Control-flow items carry tags: 1 orig, 2 dest, 3 do-sys, 4 colon-sys; a
\ mismatch is error -22 and nothing half-built stays in the dictionary.
: ?PAIRS  ( tag expected -- )  <> IF -22 THROW THEN ;
: ?COMP  ( -- )  STATE @ 0= IF -14 THROW THEN ;
: LITERAL  ( n -- )  ['] (LIT) , , ;  IMMEDIATE COMPILE-ONLY
: [  ( -- )  FALSE STATE ! ;  IMMEDIATE
: ]  ( -- )  TRUE STATE ! ;
\ A forward branch points at (NOWHERE) until it is resolved: code run with one
\ left open (a typed structure closed early by a LITERAL eating its tag, a
\ definition patched with [ DROP ]) stops with error -22 instead of jumping to 0.
: UNRESOLVED  ( -- )  -22 THROW ;
CREATE (NOWHERE)  ( -- a )  ' UNRESOLVED ,
: >MARK  ( -- orig 1 )  HERE (NOWHERE) , 1 ;
: >RESOLVE  ( orig 1 -- )  1 ?PAIRS HERE SWAP ! ;
: <MARK  ( -- dest 2 )  HERE 2 ;
: <RESOLVE  ( dest 2 -- )  2 ?PAIRS , ;
: IF  ( -- orig )  ['] ?BRANCH , >MARK ;  IMMEDIATE COMPILE-ONLY
: ELSE  ( orig -- orig' )  ['] BRANCH , >MARK 2SWAP >RESOLVE ;  IMMEDIATE COMPILE-ONLY
: THEN  ( orig -- )  >RESOLVE ;  IMMEDIATE COMPILE-ONLY
: BEGIN  ( -- dest )  <MARK ;  IMMEDIATE COMPILE-ONLY
: UNTIL  ( dest -- )  ['] ?BRANCH , <RESOLVE ;  IMMEDIATE COMPILE-ONLY
: END  ( dest -- )  ['] ?BRANCH , <RESOLVE ;  IMMEDIATE COMPILE-ONLY
: AGAIN  ( dest -- )  ['] BRANCH , <RESOLVE ;  IMMEDIATE COMPILE-ONLY
: WHILE  ( dest -- orig dest )  ['] ?BRANCH , >MARK 2SWAP ;  IMMEDIATE COMPILE-ONLY
: REPEAT  ( orig dest -- )  ['] BRANCH , <RESOLVE >RESOLVE ;  IMMEDIATE COMPILE-ONLY
\ EXIT inside a DO loop would return to its loop parameters, LEAVE and UNLOOP
\ outside one to whatever the return stack holds: refused when compiled.
VARIABLE DO-DEPTH  ( -- a ) \ DO loops open in the code being compiled
VARIABLE UNLOOPS  ( -- a ) \ UNLOOPs compiled since the last EXIT
: NO-LOOPS  ( -- )  0 DO-DEPTH !  0 UNLOOPS ! ;
: ?UNLOOPED  ( xt -- xt )
  DUP ['] LEAVE = OVER ['] UNLOOP = OR DO-DEPTH @ 0= AND
  ABORT" LEAVE or UNLOOP outside DO ... LOOP"
  DUP ['] UNLOOP = IF 1 UNLOOPS +! THEN
  DUP ['] EXIT = IF  UNLOOPS @ DO-DEPTH @ <
    ABORT" EXIT inside DO ... LOOP needs UNLOOP first"  0 UNLOOPS !  THEN ;
: COMPILE,  ( xt -- )  ?UNLOOPED , ;
: DO  ( -- do-sys )  ['] (DO) , HERE (NOWHERE) , 3  1 DO-DEPTH +! ;  IMMEDIATE COMPILE-ONLY
: ?DO  ( -- do-sys )  ['] (?DO) , HERE (NOWHERE) , 3  1 DO-DEPTH +! ;  IMMEDIATE COMPILE-ONLY
: LOOP-END  ( do-sys xt -- )  \ LOOP and +LOOP
  , 3 ?PAIRS DUP 2+ , HERE SWAP !  -1 DO-DEPTH +! ;
: LOOP  ( do-sys -- )  ['] (LOOP) LOOP-END ;  IMMEDIATE COMPILE-ONLY
: +LOOP  ( do-sys -- )  ['] (+LOOP) LOOP-END ;  IMMEDIATE COMPILE-ONLY
: ,"  ( "ccc"" -- )  [CHAR] " PARSE DUP C, HERE OVER ALLOT SWAP CMOVE ALIGN ;
: ."  ( "ccc"" -- )  ['] (.") , ," ;  IMMEDIATE COMPILE-ONLY
: ABORT"  ( "ccc"" -- )  ['] (ABORT") , ," ;  IMMEDIATE COMPILE-ONLY
CREATE SBUFS 256 ALLOT  ( -- a ) \ S" while interpreting: two buffers in turn
VARIABLE SBUF  ( -- a ) \ offset of the buffer used last
: S"  ( "text<quote>" -- a u )
  STATE @ IF ['] (S") , ," EXIT THEN
  SBUF @ 128 XOR DUP SBUF ! SBUFS +  >R
  [CHAR] " PARSE 128 MIN R@ SWAP DUP >R CMOVE 2R> ;  IMMEDIATE
: [CHAR]  ( "c" -- )  CHAR POSTPONE LITERAL ;  IMMEDIATE COMPILE-ONLY
: [']  ( "name" -- )  TICK POSTPONE LITERAL ;  IMMEDIATE COMPILE-ONLY
: [COMPILE]  ( "name" -- )  TICK , ;  IMMEDIATE COMPILE-ONLY
\ ' is FORTH-79's: IMMEDIATE, and inside a definition it compiles the address
\ as a literal (block 1008: : Install.Int.Servo ... ' Interrupt.Servo 100O ! ...).
\ Forth-94 programs use ['] there; TICK is the plain parsing word.
: '  ( "name" -- xt )  TICK STATE @ IF POSTPONE LITERAL THEN ;  IMMEDIATE
: POSTPONE  ( "name" -- )
  PARSE-NAME SEARCH-NAME ?DUP 0= IF -13 THROW THEN
  DUP NAME> SWAP C@ 128 AND IF , ELSE POSTPONE LITERAL ['] COMPILE, , THEN ;
  IMMEDIATE COMPILE-ONLY
: RECURSE  ( -- )  LAST @ NAME> , ;  IMMEDIATE COMPILE-ONLY

\ ---- headers and defining words ------------------------------------------------------
VARIABLE COLON-LFA  ( -- a ) \ header of the definition being compiled
: HEADER,  ( a u -- )  \ link into CURRENT, name as written
  DUP 0= IF -16 THROW THEN  DUP 31 > IF -19 THROW THEN
  ALIGN HERE  CURRENT @ 2 PICK CHAIN  DUP @ ,  !  HERE LAST !
  DUP C, HERE OVER ALLOT SWAP CMOVE ALIGN ;
: CF,  ( handler opcode -- )  , , ;  \ code field JSR reg,@#handler
4437O CONSTANT JSR-IP  ( -- op )
4237O CONSTANT JSR-W  ( -- op )
DOCOL CONSTANT 'DOCOL  ( -- a )
DOVAR CONSTANT 'DOVAR  ( -- a )
DOCON CONSTANT 'DOCON  ( -- a )
DODOES CONSTANT 'DODOES  ( -- a )
: IMMEDIATE  ( -- )  LAST @ DUP C@ 128 OR SWAP C! ;
: COMPILE-ONLY  ( -- )  LAST @ DUP C@ 64 OR SWAP C! ;
: SMUDGE  ( -- )  LAST @ DUP C@ 32 OR SWAP C! ;
: REVEAL  ( -- )  LAST @ DUP C@ 32 INVERT AND SWAP C! ;
: CREATE  ( "name" -- )  ?END-CODE PARSE-NAME HEADER, 'DOVAR JSR-W CF, ;
: VARIABLE  ( "name" -- )  CREATE 0 , ;
: CONSTANT  ( x "name" -- )  ?END-CODE PARSE-NAME HEADER, 'DOCON JSR-W CF, , ;
: CON  ( x "name" -- )  CONSTANT ;
: VAR  ( x "name" -- )  CREATE , ;
: ARRAY  ( n "name" -- )  CREATE CELLS DUP ALLOT HERE OVER - SWAP ERASE ;
: (DOES>)  ( -- )  R> LAST @ NAME> 2+ ! ;  COMPILE-ONLY
: DOES>  ( -- )  ['] (DOES>) , JSR-IP , 'DODOES , ;  IMMEDIATE COMPILE-ONLY
: VALUE  ( x "name" -- )  CONSTANT ;
: TO  ( x "name" -- )
  TICK >BODY STATE @ IF POSTPONE LITERAL ['] ! , ELSE ! THEN ;  IMMEDIATE
: :  ( "name" -- colon-sys )  \ also ends an open CODE word (block 1008)
  ?END-CODE  CURRENT @ CONTEXT !  NO-LOOPS  ALIGN HERE COLON-LFA !
  PARSE-NAME HEADER, SMUDGE  'DOCOL JSR-IP CF,  4 ] ;
: :NONAME  ( -- xt colon-sys )  0 COLON-LFA !  NO-LOOPS  ALIGN HERE 'DOCOL JSR-IP CF, 4 ] ;
: ;  ( colon-sys -- )
  ['] EXIT ,  4 ?PAIRS  COLON-LFA @ IF REVEAL THEN  0 COLON-LFA !  POSTPONE [ ;
  IMMEDIATE COMPILE-ONLY
: VOCABULARY  ( "name" -- )
  CREATE 0 , 0 , 0 , 0 ,  HERE VOC-LINK @ , VOC-LINK !  IMMEDIATE  DOES> CONTEXT ! ;
VOCABULARY FORTH  ( -- ) \ the kernel's vocabulary
' FORTH >BODY CONSTANT FORTH-BODY  ( -- a )
VOCABULARY ASSEMBLER  ( -- ) \ CODE's vocabulary (resident assembler: issue 4)
: DEFINITIONS  ( -- )  CONTEXT @ CURRENT ! ;
\ CODE END-CODE ;CODE: forth/kernel/code.fs (they need the resident assembler)
