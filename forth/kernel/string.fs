\ forth/kernel/string.fs: the STRING and STRING EXT word sets (Forth-2012 17)
\ beyond /STRING CMOVE CMOVE> COMPARE (prims.fs, core.fs).

: -TRAILING  ( a u -- a u' )  \ STRING: without trailing blanks
  BEGIN DUP WHILE 2DUP + 1- C@ BL = WHILE 1- REPEAT THEN ;
: BLANK  ( a u -- )  BL FILL ;  \ STRING
: SLITERAL  ( a u -- )  ['] (S") , S, ;  IMMEDIATE COMPILE-ONLY  \ STRING
: SEARCH  ( a1 u1 a2 u2 -- a3 u3 f )  \ STRING: a3 u3 from the first match on
  2>R 2DUP BEGIN DUP R@ < 0= WHILE
    OVER R@ 2R@ COMPARE 0= IF 2SWAP 2DROP 2R> 2DROP TRUE EXIT THEN  1 /STRING
  REPEAT 2DROP 2R> 2DROP FALSE ;

\ ---- STRING EXT: text substitution ---------------------------------------------
\ REPLACES keeps each name as a word of the word list SUBSTITUTIONS whose body
\ points to the counted text; SUBSTITUTE replaces %name% by it and %% by %,
\ in one pass; a source overlapping the buffer is first copied to the top of
\ the free dictionary space (n = -1 if the buffer overlaps that too).
VOCABULARY SUBSTITUTIONS  ( -- ) \ the names REPLACES defined (not for searching)
' SUBSTITUTIONS >BODY CONSTANT SUBSTS  ( -- wid )
: REPLACES  ( a1 u1 a2 u2 -- )  \ STRING EXT: %a2% becomes the text a1 u1
  2DUP SUBSTS WID-FIND ?DUP IF NIP NIP NAME> >BODY ELSE
    LAST @ >R  CURRENT @ >R  SUBSTS CURRENT !  HEADER, 'DOVAR JSR-W CF,  HERE 0 ,
    R> CURRENT !  R> LAST ! THEN
  >R  HERE R> !  S, ;  \ a replaced text stays in the dictionary, unreferenced
VARIABLE SUB-DST  ( -- a ) \ SUBSTITUTE: where the next character goes
VARIABLE SUB-END  ( -- a ) \ the end of its destination buffer
VARIABLE #SUBS  ( -- a ) \ substitutions made, -1 after an overflow
: SUB-PUT  ( a u -- )  \ append to the destination, or mark an overflow
  DUP SUB-DST @ + SUB-END @ U> IF 2DROP -1 #SUBS ! EXIT THEN
  SUB-DST @ SWAP DUP SUB-DST +! MOVE ;
: SUB-TEXT  ( a u -- )  \ the text of %name%, or %name% as it was when undefined
  2DUP SUBSTS WID-FIND ?DUP IF NIP NIP NAME> >BODY @ COUNT SUB-PUT
    #SUBS @ 0< 0= IF 1 #SUBS +! THEN EXIT THEN
  S" %" SUB-PUT SUB-PUT S" %" SUB-PUT ;
: SUB-PERCENT  ( a u -- a' u' )  \ at a %: %% or %name% or a last lone %
  1 /STRING  2DUP [CHAR] % SCAN DUP 0= IF 2DROP S" %" SUB-PUT EXIT THEN
  2SWAP DROP 2 PICK OVER -  ?DUP IF SUB-TEXT ELSE DROP S" %" SUB-PUT THEN
  1 /STRING ;
: OVERLAP?  ( a1 u1 a2 u2 -- f )  \ do the two strings share a byte?
  OVER + >R  ( a1 u1 a2 ; R: end2 )  -ROT OVER + ( a2 a1 end1 )
  ROT U> SWAP R> U< AND ;
: SUB-SOURCE  ( a1 u1 a2 u2 -- a1' u1 a2 u2 )  \ a source in the way goes below DICT-END
  2OVER 2OVER OVERLAP? IF 2SWAP DICT-END @ OVER - >R TUCK R@ SWAP MOVE R> SWAP 2SWAP THEN ;
: SUBSTITUTE  ( a1 u1 a2 u2 -- a2 u3 n )  \ STRING EXT; n < 0: a2 u2 too small
  SUB-SOURCE  2OVER 2OVER OVERLAP? IF 2SWAP 2DROP -1 EXIT THEN
  OVER + SUB-END !  DUP SUB-DST !  0 #SUBS !  >R
  BEGIN DUP WHILE
    OVER C@ [CHAR] % = IF SUB-PERCENT ELSE OVER 1 SUB-PUT 1 /STRING THEN
  REPEAT 2DROP  R> SUB-DST @ OVER - #SUBS @ ;
: UNESCAPE  ( a1 u1 a2 -- a2 u2 )  \ STRING EXT: every % doubled
  DUP >R -ROT OVER + SWAP ?DO
    I C@ [CHAR] % = IF [CHAR] % OVER C! 1+ THEN  I C@ OVER C! 1+
  LOOP R> TUCK - ;
