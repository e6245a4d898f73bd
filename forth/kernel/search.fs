\ forth/kernel/search.fs: the SEARCH and SEARCH EXT word sets on the search
\ order of interp.fs (CONTEXT's cells, #ORDER of them). FORTH-79's vocabulary
\ words (FORTH ASSEMBLER EDITOR) replace the first word list, as ALSO/ONLY
\ systems did, so the 1983 blocks' ASSEMBLER ... FORTH works unchanged.

8 CONSTANT #WORDLISTS  ( -- n ) \ the most word lists in the search order
: FORTH-WORDLIST  ( -- wid )  FORTH-BODY ;  \ SEARCH
: WORDLIST  ( -- wid )  0 WORDLIST, ;  \ SEARCH: a new, empty, nameless word list
: GET-CURRENT  ( -- wid )  CURRENT @ ;  \ SEARCH
: SET-CURRENT  ( wid -- )  CURRENT ! ;  \ SEARCH
: GET-ORDER  ( -- widn .. wid1 n )  \ SEARCH: wid1 is searched first
  CONTEXT #ORDER @ 2* + BEGIN DUP CONTEXT <> WHILE 2- DUP @ SWAP REPEAT DROP
  #ORDER @ ;
: ONLY  ( -- )  FORTH-BODY CONTEXT !  1 #ORDER ! ;  \ SEARCH EXT: the minimum order
: SET-ORDER  ( widn .. wid1 n -- )  \ SEARCH; n = -1: the minimum order
  DUP -1 = IF DROP ONLY EXIT THEN
  DUP #WORDLISTS U> IF -49 THROW THEN
  DUP #ORDER !  2* CONTEXT + CONTEXT ?DO I ! 2 +LOOP ;
: ALSO  ( -- )  \ SEARCH EXT: duplicate the first word list
  #ORDER @ #WORDLISTS = IF -49 THROW THEN
  CONTEXT DUP 2+ #ORDER @ 2* MOVE  1 #ORDER +! ;
: PREVIOUS  ( -- )  \ SEARCH EXT: drop the first word list
  #ORDER @ 0= IF -50 THROW THEN
  -1 #ORDER +!  CONTEXT 2+ CONTEXT #ORDER @ 2* MOVE ;
: .WID  ( wid -- )  DUP VOC-NAME ?DUP IF .NAME DROP ELSE .OCTAL THEN SPACE ;
: ORDER  ( -- )  \ SEARCH EXT: the search order, first searched first; CURRENT
  CR #ORDER @ 2* CONTEXT + CONTEXT ?DO I @ .WID 2 +LOOP
  ."   definitions: " CURRENT @ .WID ;

\ ---- ENVIRONMENT? (CORE): the answers are words of a word list of their own --
VOCABULARY ENVIRONMENT  ( -- ) \ the ENVIRONMENT? queries (SEARCH them by name)
ENVIRONMENT DEFINITIONS
255 CONSTANT /COUNTED-STRING  ( -- n ) \ longest counted string
68 CONSTANT /HOLD  ( -- n ) \ pictured numeric output buffer, characters
92 CONSTANT /PAD  ( -- n ) \ PAD's size
8 CONSTANT ADDRESS-UNIT-BITS  ( -- n ) \ bits in an address unit: a byte (cells are 16)
0 CONSTANT FLOORED  ( -- f ) \ / MOD */ round towards zero (SM/REM)
255 CONSTANT MAX-CHAR  ( -- u )
32767 CONSTANT MAX-N  ( -- n )
-1 CONSTANT MAX-U  ( -- u )
: MAX-D  ( -- d )  -1 32767 ;
: MAX-UD  ( -- ud )  -1 -1 ;
216 CONSTANT STACK-CELLS  ( -- n ) \ data stack, up to the overflow check
203 CONSTANT RETURN-STACK-CELLS  ( -- n ) \ return stack, down to DOCOL's and >R's check
8 CONSTANT WORDLISTS  ( -- n ) \ SEARCH: word lists in the search order
16 CONSTANT #LOCALS  ( -- n ) \ LOCALS: locals in one definition
FORTH DEFINITIONS
: ENVIRONMENT?  ( a u -- false | i*x true )  \ CORE
  ['] ENVIRONMENT >BODY SEARCH-WORDLIST IF EXECUTE TRUE ELSE FALSE THEN ;
