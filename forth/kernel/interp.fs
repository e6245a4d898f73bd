\ forth/kernel/interp.fs: the input source, parsing, lookup, the compiler's words,
\ vocabularies (the outer interpreter, error reports and QUIT: quit.fs).

\ ---- the input source ---------------------------------------------------------
: SOURCE  ( -- a u )  BLK @ IF BLK @ (BLOCK) 1024 ELSE SRC 2@ THEN ;  \ CORE: (BLOCK): disk.fs
: REST  ( -- a u )  \ unparsed part of the source
  SOURCE >IN @ OVER MIN /STRING ;
: PARSE  ( c -- a u )  \ CORE EXT
  >R REST OVER SWAP R> SCAN  ( a a' u' )  0<> 1 AND >R  OVER -  DUP R> + >IN +! ;
: PARSE-NAME  ( -- a u )  \ CORE EXT
  REST BL SKIP DROP SOURCE DROP - >IN !  BL PARSE ;
: WORD  ( c -- ca )  \ CORE: counted string at HERE, a blank after it
  >R REST R@ SKIP DROP SOURCE DROP - >IN !  R> PARSE
  DUP HERE C! HERE 1+ SWAP CMOVE  BL HERE COUNT + C!  HERE ;
: CHAR  ( "c" -- c )  PARSE-NAME DROP C@ ;  \ CORE
: (  ( "text<paren>" -- )  [CHAR] ) PARSE 2DROP ;  IMMEDIATE  \ CORE
: \  ( "line" -- )  \ CORE EXT, BLOCK EXT: in a block, to the end of the 64-character line
  BLK @ IF >IN @ 63 + -64 AND >IN ! ELSE SOURCE NIP >IN ! THEN ;  IMMEDIATE
: .(  ( "text<paren>" -- )  [CHAR] ) PARSE TYPE ;  IMMEDIATE  \ CORE EXT

\ ---- numbers: Forth-2012 3.4.1.3 plus the project's trailing O ----------------
\ 'c' a character; a prefix # $ % (decimal, hex, binary) for this number only;
\ then an optional -, digits in BASE, and a trailing O (octal, in a base up to
\ 24: from 25 on O is a digit) or a trailing . (a double-cell number).
: DIGIT?  ( c -- n true | false )
  UPC DUP [CHAR] 9 > IF DUP [CHAR] A < IF DROP FALSE EXIT THEN 7 - THEN
  [CHAR] 0 - DUP BASE @ U< IF TRUE ELSE DROP FALSE THEN ;
: UD*  ( ud u -- ud' )  DUP >R UM* DROP SWAP R> UM* ROT + ;
: >NUMBER  ( ud a u -- ud' a' u' )  \ CORE
  BEGIN DUP WHILE OVER C@ DIGIT? WHILE
    >R 2SWAP BASE @ UD* R> 0 D+ 2SWAP 1 /STRING
  REPEAT THEN ;
: CHAR-LITERAL?  ( a u -- c true | a u false )  \ 'c'
  DUP 3 = IF OVER C@ [CHAR] ' = IF OVER 2+ C@ [CHAR] ' = IF
    DROP 1+ C@ TRUE EXIT THEN THEN THEN  FALSE ;
: PREFIX-BASE  ( c -- base | 0 )
  DUP [CHAR] # = IF DROP 10 EXIT THEN  DUP [CHAR] $ = IF DROP 16 EXIT THEN
  [CHAR] % = IF 2 ELSE 0 THEN ;
: LAST-CHAR?  ( a u c -- a u' f )  \ strip a last character c (not the only one)
  >R DUP 1 > IF 2DUP + 1- C@ UPC R@ = IF 1- R> DROP TRUE EXIT THEN THEN
  R> DROP FALSE ;
VARIABLE NUM-CELLS  ( -- a ) \ 1 or 2: the number being converted
: NUMBER?  ( a u -- n 1 | d 2 | a u 0 )
  ?BASE  CHAR-LITERAL? IF 1 EXIT THEN
  2DUP BASE @ >R
  DUP IF OVER C@ PREFIX-BASE ?DUP IF BASE ! 1 /STRING THEN THEN
  [CHAR] . LAST-CHAR? IF 2 ELSE 1 THEN NUM-CELLS !
  BASE @ 25 < IF [CHAR] O LAST-CHAR? IF 8 BASE ! THEN THEN
  DUP IF OVER C@ [CHAR] - = ELSE FALSE THEN DUP >R IF 1 /STRING THEN
  DUP IF 0 0 2SWAP >NUMBER NIP ELSE 2DROP 0 0 1 THEN
  R> SWAP R> BASE !  ( a u lo hi neg rest )
  IF 2DROP DROP 0 EXIT THEN
  IF DNEGATE THEN 2SWAP 2DROP  NUM-CELLS @ 1 = IF DROP THEN  NUM-CELLS @ ;

\ ---- finding words: word lists and the search order ----------------------------
\ A word list (wid) is the body of a VOCABULARY or the space WORDLIST allots:
\ +0 .. +76 (octal) the newest LFA of each of its 32 chains (a name's chain:
\ prims.fs CHAIN-OFFSET, its first character and length), +100 its VOC-LINK
\ cell, +102 the vocabulary's name field (0 for a WORDLIST). The search order is CONTEXT's
\ cells, CONTEXT @ searched first; a wid equal to the one before it is not
\ searched again (FORTH FORTH at boot: FORTH-79's CONTEXT then FORTH, and a
\ vocabulary word replaces CONTEXT @).
#chains EQU #CHAINS      \ chains per word list (the metacompiler's #chains)
#chains 2* EQU CHAIN-BYTES
: WID>LINK  ( wid -- a )  CHAIN-BYTES + ;  \ its VOC-LINK cell
: LINK>WID  ( a -- wid )  CHAIN-BYTES - ;
CODE CHAIN  ( a u wid -- a u head )  \ the cell heading name a u's chain in wid
  W S )+ MOV,  CHAIN-OFFSET @# PC JSR,  R0 W ADD,  S -) R0 MOV,  NEXT,  END-CODE
CODE WID-FIND  ( a u wid -- nfa | 0 )  \ the newest word named a u in word list wid
  W S )+ MOV,  S ) TST,
  NE IF,  RP -) IP MOV,  CHAIN-OFFSET @# PC JSR,  R0 W ADD,  W R0 ) MOV,
    WALK @# PC JSR,  IP RP )+ MOV,
  ELSE,  W CLR,  THEN,
  S 2 # ADD,  S ) W MOV,  NEXT,  END-CODE
CODE SEARCH-ORDER  ( a u -- nfa | 0 )  \ in CONTEXT's #ORDER word lists, in order
  S ) TST,  EQ IF,  S 2 # ADD,  S ) CLR,  NEXT,  THEN,
  RP -) IP MOV,  CHAIN-OFFSET @# PC JSR,
  RP -) R0 MOV,                          \ 6(RP): the chain's offset
  RP -) ' #ORDER >BODY @# MOV,           \ 4(RP): word lists left
  RP -) ' CONTEXT >BODY # MOV,           \ 2(RP): the next one's cell
  RP -) CLR,                             \ (RP): the word list before it
  BEGIN,  4 RP I) DEC,  PL WHILE,
    R0 2 RP I) MOV,  W R0 )+ MOV,  2 RP I) R0 MOV,
    W RP ) CMP,  NE IF,
      RP ) W MOV,  W 6 RP I) ADD,  W W ) MOV,  WALK @# PC JSR,
      NE IF,  RP 10O # ADD,  IP RP )+ MOV,  S 2 # ADD,  S ) W MOV,  NEXT,  THEN,
    THEN,
  REPEAT,
  RP 10O # ADD,  IP RP )+ MOV,  S 2 # ADD,  S ) CLR,  NEXT,  END-CODE
: SEARCH-NAME  ( a u -- nfa | 0 )  \ the locals while compiling, the search order
  STATE @ IF LOCALS-HERE @ LOCALS-AREA <> IF
    2DUP LOCAL-FIND ?DUP IF NIP NIP EXIT THEN THEN THEN
  SEARCH-ORDER ;
: UMAX  ( u1 u2 -- u )  2DUP U< IF SWAP THEN DROP ;
CODE NEWEST-SLOT  ( heads -- slot | 0 )  \ the cell holding the newest header
  W S ) MOV,  R3 W MOV,  R3 CHAIN-BYTES # ADD,  R0 CLR,  T CLR,
  BEGIN,
    W ) R0 CMP,  LO IF,  R0 W ) MOV,  T W MOV,  THEN,
    W 2 # ADD,  R3 W CMP,
  EQ UNTIL,
  S ) T MOV,  NEXT,  END-CODE
: NEWEST  ( voc -- lfa | 0 )  NEWEST-SLOT DUP IF @ THEN ;
: NFA>XT  ( nfa -- xt 1 | xt -1 )  \ 1 when IMMEDIATE
  DUP NAME> SWAP C@ 128 AND IF 1 ELSE -1 THEN ;
: FIND  ( ca -- ca 0 | xt 1 | xt -1 )  \ CORE, SEARCH
  DUP COUNT SEARCH-NAME DUP IF NIP NFA>XT THEN ;
: SEARCH-WORDLIST  ( a u wid -- 0 | xt 1 | xt -1 )  \ SEARCH
  WID-FIND DUP IF NFA>XT THEN ;
: ?NAME  ( a u -- nfa )  \ found in the search order, or error -13 naming it
  2DUP SEARCH-NAME ?DUP IF NIP NIP EXIT THEN  WHAT 2! -13 THROW ;
: TICK  ( "name" -- xt )  PARSE-NAME ?NAME NAME> ;

\ ---- compiling ---------------------------------------------------------------------
\ Control-flow items carry tags: 1 orig, 2 dest, 3 do-sys, 4 colon-sys; a
\ mismatch is error -22 and nothing half-built stays in the dictionary.
: ?PAIRS  ( tag expected -- )  <> IF -22 THROW THEN ;
: ?COMP  ( -- )  STATE @ 0= IF -14 THROW THEN ;
: LITERAL  ( n -- )  ['] (LIT) , , ;  IMMEDIATE COMPILE-ONLY  \ CORE
: [  ( -- )  FALSE STATE ! ;  IMMEDIATE  \ CORE
: ]  ( -- )  TRUE STATE ! ;  \ CORE
: NUMBER  ( a u -- n | d )  \ a number for the interpreter, compiled when compiling
  NUMBER? DUP 0= IF -13 THROW THEN
  STATE @ IF 2 = IF SWAP POSTPONE LITERAL THEN POSTPONE LITERAL ELSE DROP THEN ;
\ A forward branch points at (NOWHERE) until it is resolved: code run with one
\ left open (a typed structure closed early by a LITERAL eating its tag, a
\ definition patched with [ DROP ]) stops with error -22 instead of jumping to 0.
: UNRESOLVED  ( -- )  -22 THROW ;
CREATE (NOWHERE)  ( -- a )  ' UNRESOLVED ,
: >MARK  ( -- orig 1 )  HERE (NOWHERE) , 1 ;
: >RESOLVE  ( orig 1 -- )  1 ?PAIRS HERE SWAP ! ;
: <MARK  ( -- dest 2 )  HERE 2 ;
: <RESOLVE  ( dest 2 -- )  2 ?PAIRS , ;
: IF  ( -- orig )  ['] ?BRANCH , >MARK ;  IMMEDIATE COMPILE-ONLY  \ CORE
: ELSE  ( orig -- orig' )  ['] BRANCH , >MARK 2SWAP >RESOLVE ;  IMMEDIATE COMPILE-ONLY  \ CORE
: THEN  ( orig -- )  >RESOLVE ;  IMMEDIATE COMPILE-ONLY  \ CORE
: BEGIN  ( -- dest )  <MARK ;  IMMEDIATE COMPILE-ONLY  \ CORE
: UNTIL  ( dest -- )  ['] ?BRANCH , <RESOLVE ;  IMMEDIATE COMPILE-ONLY  \ CORE
: END  ( dest -- )  ['] ?BRANCH , <RESOLVE ;  IMMEDIATE COMPILE-ONLY
: AGAIN  ( dest -- )  ['] BRANCH , <RESOLVE ;  IMMEDIATE COMPILE-ONLY  \ CORE EXT
: WHILE  ( dest -- orig dest )  ['] ?BRANCH , >MARK 2SWAP ;  IMMEDIATE COMPILE-ONLY  \ CORE
: REPEAT  ( orig dest -- )  ['] BRANCH , <RESOLVE >RESOLVE ;  IMMEDIATE COMPILE-ONLY  \ CORE
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
: COMPILE,  ( xt -- )  ?UNLOOPED , ;  \ CORE EXT
: DO  ( -- do-sys )  ['] (DO) , HERE (NOWHERE) , 3  1 DO-DEPTH +! ;  IMMEDIATE COMPILE-ONLY  \ CORE
: ?DO  ( -- do-sys )  ['] (?DO) , HERE (NOWHERE) , 3  1 DO-DEPTH +! ;  IMMEDIATE COMPILE-ONLY  \ CORE EXT
: LOOP-END  ( do-sys xt -- )  \ LOOP and +LOOP
  , 3 ?PAIRS DUP 2+ , HERE SWAP !  -1 DO-DEPTH +! ;
: LOOP  ( do-sys -- )  ['] (LOOP) LOOP-END ;  IMMEDIATE COMPILE-ONLY  \ CORE
: +LOOP  ( do-sys -- )  ['] (+LOOP) LOOP-END ;  IMMEDIATE COMPILE-ONLY  \ CORE
: S,  ( a u -- )  DUP C, HERE OVER ALLOT SWAP CMOVE ALIGN ;  \ a counted string, aligned
: ,"  ( "ccc"" -- )  [CHAR] " PARSE S, ;
: ."  ( "ccc"" -- )  ['] (.") , ," ;  IMMEDIATE COMPILE-ONLY  \ CORE
: ABORT"  ( "ccc"" -- )  ['] (ABORT") , ," ;  IMMEDIATE COMPILE-ONLY  \ CORE, EXCEPTION EXT
CREATE SBUFS 512 ALLOT  ( -- a ) \ S" while interpreting: a ring of strings
VARIABLE SBUF  ( -- a ) \ offset of the next free byte in it
: SBUF-COPY  ( a u -- a' u )  \ into the ring, from its start when it does not
  DUP 256 > IF -18 THROW THEN  \ fit: the newest strings stay (two of 256, or more)
  SBUF @ OVER + 512 > IF 0 SBUF ! THEN  SBUF @ SBUFS +  OVER ALIGNED SBUF +!
  SWAP 2DUP 2>R CMOVE 2R> ;
: S"  ( "text<quote>" -- a u )  \ CORE
  STATE @ IF ['] (S") , ," EXIT THEN  [CHAR] " PARSE SBUF-COPY ;  IMMEDIATE
: [CHAR]  ( "c" -- )  CHAR POSTPONE LITERAL ;  IMMEDIATE COMPILE-ONLY  \ CORE
: [']  ( "name" -- )  TICK POSTPONE LITERAL ;  IMMEDIATE COMPILE-ONLY  \ CORE
: [COMPILE]  ( "name" -- )  TICK , ;  IMMEDIATE COMPILE-ONLY  \ CORE EXT
\ ' is FORTH-79's: IMMEDIATE, and inside a definition it compiles the address
\ as a literal (block 1008: : Install.Int.Servo ... ' Interrupt.Servo 100O ! ...).
\ Forth-94 programs use ['] there; TICK is the plain parsing word.
: '  ( "name" -- xt )  TICK STATE @ IF POSTPONE LITERAL THEN ;  IMMEDIATE  \ CORE
\ A postponed IMMEDIATE word runs in compile state wherever the word holding
\ it runs (gforth's postpone.fs: : ps POSTPONE S" ;  : t [ ps XY" ] ; lays
\ XY into t); a STATE it changed itself (POSTPONE [) is kept.
: COMPILING  ( i*x xt -- j*x )
  STATE @ >R  ]  (EXECUTE)  STATE @ IF R> STATE ! ELSE R> DROP THEN ;
: POSTPONE  ( "name" -- )  \ CORE
  PARSE-NAME ?NAME  DUP NAME> SWAP C@ 128 AND
  IF POSTPONE LITERAL ['] COMPILING , ELSE POSTPONE LITERAL ['] COMPILE, , THEN ;
  IMMEDIATE COMPILE-ONLY
: RECURSE  ( -- )  \ CORE: 0 = the last definition was forgotten or cut short
  LAST-XT @ ?DUP 0= IF -14 THROW THEN , ;  IMMEDIATE COMPILE-ONLY

\ ---- headers and defining words ------------------------------------------------------
VARIABLE COLON-LFA  ( -- a ) \ header of the definition being compiled
VARIABLE LAST-XT  ( -- a ) \ xt of the newest : or :NONAME definition (RECURSE)
: HEADER,  ( a u -- )  \ link into CURRENT, name as written
  DUP 0= IF -16 THROW THEN  DUP 31 > IF -19 THROW THEN
  ALIGN CURRENT @ CHAIN  HERE OVER @ ,  SWAP !  HERE LAST !
  DUP C, HERE OVER ALLOT SWAP CMOVE ALIGN ;
: CF,  ( handler opcode -- )  , , ;  \ code field JSR reg,@#handler
4437O CONSTANT JSR-IP  ( -- op )
4237O CONSTANT JSR-W  ( -- op )
DOCOL CONSTANT 'DOCOL  ( -- a )
DOVAR CONSTANT 'DOVAR  ( -- a )
DOCON CONSTANT 'DOCON  ( -- a )
DODOES CONSTANT 'DODOES  ( -- a )
: IMMEDIATE  ( -- )  LAST @ DUP C@ 128 OR SWAP C! ;  \ CORE
: COMPILE-ONLY  ( -- )  LAST @ DUP C@ 64 OR SWAP C! ;
: SMUDGE  ( -- )  LAST @ DUP C@ 32 OR SWAP C! ;
: REVEAL  ( -- )  LAST @ DUP C@ 32 INVERT AND SWAP C! ;
: CREATE  ( "name" -- )  ?END-CODE PARSE-NAME HEADER, 'DOVAR JSR-W CF, ;  \ CORE
: VARIABLE  ( "name" -- )  CREATE 0 , ;  \ CORE
: CONSTANT  ( x "name" -- )  ?END-CODE PARSE-NAME HEADER, 'DOCON JSR-W CF, , ;  \ CORE
: CON  ( x "name" -- )  CONSTANT ;  \ the appendix's constant
: VAR  ( x "name" -- )  CREATE , ;  \ the appendix's variable with a value
: ARRAY  ( n "name" -- )  CREATE CELLS DUP ALLOT HERE OVER - SWAP ERASE ;  \ the appendix's n cells
: (DOES>)  ( -- )  R> LAST @ NAME> 2+ ! ;  COMPILE-ONLY
: DOES>  ( -- )  LOCALS-LEAVE, LOCALS-CLEAR  ['] (DOES>) , JSR-IP , 'DODOES , ;  IMMEDIATE COMPILE-ONLY  \ CORE
: VALUE  ( x "name" -- )  CONSTANT ;  \ CORE EXT (TO stores into it)
: TO  ( x "name" -- )  \ CORE EXT, DOUBLE EXT
  TICK >BODY STATE @ IF POSTPONE LITERAL ['] ! , ELSE ! THEN ;  IMMEDIATE
: VOC-NAME  ( wid -- nfa | 0 )  WID>LINK 2+ @ ;  \ 0: a WORDLIST, not a VOCABULARY
\ FORTH-79: : sets CONTEXT to CURRENT. Done only when both are vocabularies, so
\ that word lists and search orders of standard programs stay as they set them.
: COLON-CONTEXT  ( -- )
  CONTEXT @ VOC-NAME 0<> CURRENT @ VOC-NAME 0<> AND IF CURRENT @ VOC-CONTEXT THEN ;
: :  ( "name" -- colon-sys )  \ CORE: also ends an open CODE word (block 1008)
  ?END-CODE  COLON-CONTEXT  LOCALS-CLEAR  NO-LOOPS  ALIGN HERE COLON-LFA !
  PARSE-NAME HEADER, SMUDGE  HERE LAST-XT !  'DOCOL JSR-IP CF,  4 ] ;
: :NONAME  ( -- xt colon-sys )  \ CORE EXT
  0 COLON-LFA !  LOCALS-CLEAR  NO-LOOPS  ALIGN HERE DUP LAST-XT !  'DOCOL JSR-IP CF, 4 ] ;
: ;  ( colon-sys -- )  \ CORE
  LOCALS-LEAVE,  ['] EXIT ,  4 ?PAIRS  LOCALS-CLEAR  COLON-LFA @ IF REVEAL THEN  0 COLON-LFA !  POSTPONE [ ;
  IMMEDIATE COMPILE-ONLY
: WORDLIST,  ( nfa -- wid )  \ an empty word list, linked from VOC-LINK
  ALIGN HERE  CHAIN-BYTES ALLOT  DUP CHAIN-BYTES ERASE
  HERE VOC-LINK @ , VOC-LINK !  SWAP , ;
: VOCABULARY  ( "name" -- )  \ FORTH-79: the name replaces CONTEXT @ (immediate)
  CREATE LAST @ WORDLIST, DROP  IMMEDIATE  DOES> VOC-CONTEXT ;
VOCABULARY FORTH  ( -- ) \ SEARCH EXT: the kernel's vocabulary
' FORTH >BODY CONSTANT FORTH-BODY  ( -- a )
\ FORTH-79: every vocabulary chains to FORTH. After ONLY (one word list) a
\ vocabulary other than FORTH that replaces it gets FORTH behind it, so
\ ONLY FORTH DEFINITIONS 1000 LOAD still finds ( inside ASSEMBLER.
: VOC-CONTEXT  ( wid -- )  \ the first word list := wid
  DUP CONTEXT !  FORTH-BODY <> #ORDER @ 2 < AND IF FORTH-BODY CONTEXT 2+ !  2 #ORDER ! THEN ;
VOCABULARY ASSEMBLER  ( -- ) \ TOOLS EXT: CODE's vocabulary
' ASSEMBLER >BODY CONSTANT ASSEMBLER-BODY  ( -- a )
: DEFINITIONS  ( -- )  CONTEXT @ CURRENT ! ;  \ SEARCH
\ CODE END-CODE ;CODE: forth/kernel/code.fs (they need the resident assembler)
