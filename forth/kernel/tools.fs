\ forth/kernel/tools.fs: .S WORDS DUMP SEE, FORGET and MARKER.

: .S  ( -- )  \ TOOLS: the stack, deepest first
  ." <" DEPTH 0 .R ." > "  DEPTH DUP 0 ?DO DUP I - PICK . LOOP DROP ;
VARIABLE COLUMN  ( -- a )
\ WORDS keeps its place in each chain at HERE (scratch, as WORD's buffer):
\ the bytes a cursor array in the dictionary would take stay free
: WORDS  ( -- )  \ TOOLS: the CONTEXT vocabulary, newest first (its chains merged)
  0 COLUMN !  CONTEXT @ HERE CHAIN-BYTES CMOVE
  BEGIN HERE NEWEST-SLOT ?DUP WHILE
    DUP @ DUP 2+ C@ 32 AND 0= IF
      COLUMN @ 64 > IF CR 0 COLUMN ! THEN
      DUP 2+ DUP .NAME SPACE C@ 31 AND 1+ COLUMN +!
    THEN @ SWAP !
  REPEAT ;
: DUMP  ( a u -- )  \ TOOLS: bytes in BASE, then as characters
  OVER + SWAP ?DO
    CR I 6 U.R ." : "  I 16 + I ?DO I C@ 4 U.R LOOP  SPACE
    I 16 + I ?DO I C@ DUP BL 127 WITHIN 0= IF DROP [CHAR] . THEN EMIT LOOP
  16 +LOOP CR ;

\ ---- SEE: decompile a colon definition; a CODE word through DISASSEMBLE-CODE ------------
: .XT  ( xt -- )  DUP >NAME ?DUP IF NIP .NAME ELSE ." [" .OCTAL ." ]" THEN SPACE ;
: INLINE-STRING?  ( xt -- f )
  DUP ['] (.") = OVER ['] (S") = OR SWAP ['] (ABORT") = OR ;
: BRANCHING?  ( xt -- f )  \ words followed by a target address
  DUP ['] BRANCH = OVER ['] ?BRANCH = OR OVER ['] (DO) = OR OVER ['] (?DO) = OR
  OVER ['] (LOOP) = OR SWAP ['] (+LOOP) = OR ;
: SEE-COLON  ( body -- )
  DUP BEGIN  ( far a )
    DUP @  ( far a xt )
    DUP ['] (LIT) = IF DROP 2+ DUP @ . ELSE  DUP .XT
    DUP LOCAL-OPERAND? IF DROP 2+ DUP @ . ELSE
    DUP INLINE-STRING? IF DROP 2+ DUP COUNT TYPE [CHAR] " EMIT SPACE DUP C@ + 1- ALIGNED
    ELSE DUP BRANCHING? IF DROP 2+ DUP @ DUP ." ->" .OCTAL SPACE ROT UMAX SWAP
    ELSE ['] EXIT = IF 2DUP SWAP U< 0= IF 2DROP EXIT THEN THEN THEN THEN THEN THEN
    2+
  AGAIN ;
: SEE  ( "name" -- )  \ TOOLS
  TICK CR DUP >NAME ?DUP IF .NAME SPACE THEN
  DUP @ JSR-IP = OVER 2+ @ 'DOCOL = AND IF ." is : " 4 + SEE-COLON ." ;" CR EXIT THEN
  DUP @ JSR-W = IF DUP 2+ @
    DUP 'DOVAR = IF DROP ." is CREATE / VARIABLE, body at " >BODY .OCTAL CR EXIT THEN
    DUP 'DOCON = IF DROP ." is CONSTANT " >BODY @ . CR EXIT THEN
    ." has DOES> code at " .OCTAL ." , body at " >BODY .OCTAL CR EXIT THEN
  ." is CODE at " DUP .OCTAL  \ in mnemonics once blocks 1090-1097 (a disassembler) are loaded
  S" DISASSEMBLE-CODE" FORTH-BODY SEARCH-WORDLIST IF EXECUTE EXIT THEN
  ." : " 8 0 DO DUP @ .OCTAL SPACE 2+ LOOP DROP CR ." (1090 LOAD: SEE then disassembles)" CR ;

\ ---- FORGET and MARKER -----------------------------------------------------------
: TRIM-CHAIN  ( lfa head -- )  \ unlink chain entries at or above lfa
  BEGIN 2DUP @ SWAP U< 0= OVER @ 0<> AND WHILE DUP @ @ OVER ! REPEAT 2DROP ;
: TRIM  ( lfa body -- )  #CHAINS 0 DO 2DUP I 2* + TRIM-CHAIN LOOP 2DROP ;
: TRIM-VOCS  ( lfa -- )  \ trim every vocabulary; drop forgotten vocabularies
  VOC-LINK BEGIN DUP @ WHILE
    DUP @ 2 PICK U< 0= IF DUP @ @ OVER ! ELSE 2DUP @ LINK>WID TRIM @ THEN
  REPEAT 2DROP ;
: RESTORE-VECTORS  ( lfa -- )  \ no vector may point into forgotten code
  1000O 100O DO  \ those below 100 and 250 are the kernel's: ! refuses them
    I 250O <> IF I @ STUBS I + <> IF I @ OVER HERE WITHIN IF
      STUBS I + I !  ." vector " I .OCTAL ."  restored to its default handler" CR
    THEN THEN THEN
  4 +LOOP DROP ;
: (FORGET)  ( lfa -- )  \ remove every word from lfa up
  DUP FENCE @ U< IF -15 THROW THEN
  DUP RESTORE-VECTORS  DUP TRIM-VOCS
  LAST-XT @ OVER U< 0= IF 0 LAST-XT ! THEN  \ RECURSE must not call forgotten code
  #ORDER @ 2* CONTEXT + CONTEXT ?DO  \ forgotten word lists leave the search order
    I @ OVER U< 0= IF FORTH-BODY I ! THEN  2 +LOOP
  CURRENT @ OVER U< 0= IF FORTH-BODY CURRENT ! THEN
  DP !  CURRENT @ NEWEST 2+ LAST ! ;
: FORGET  ( "name" -- )  \ TOOLS EXT
  PARSE-NAME 2DUP CURRENT @ WID-FIND ?DUP 0= IF WHAT 2! -13 THROW THEN
  NIP NIP 2- (FORGET) ;
: MARKER  ( "name" -- )  ALIGN HERE CREATE , DOES> @ (FORGET) ;  \ CORE EXT
