\ forth/meta/kmacros.fs: host-side assembler macros used by the kernel's CODE
\ words (gforth words in the FORTH wordlist, found by the metacompiler's
\ interpreter inside CODE bodies). One place for patterns several words share.
>asm
\ ( a b -- flag ), flag true when "a cond b" holds (cond as after CMP a-b)
: BINCMP, ( cond -- )
  R0 S )+ MOV,  T CLR,  R0 S ) CMP,  IF, T DEC, THEN,  S ) T MOV,  NEXT, ;
\ ( a -- flag ), flag true when "a cond 0" holds
: UNCMP, ( cond -- )
  T CLR,  S ) TST,  IF, T DEC, THEN,  S ) T MOV,  NEXT, ;
\ R3 = the character at W; when the delimiter in R0 is a blank, every control
\ character (tab, ...) reads as a blank too
: BLANKCHAR, ( -- )
  R3 W ) MOVB,  R3 $FF00 # BIC,
  32 # R0 CMP,  EQ IF,  32 # R3 CMP,  LOS IF,  R3 32 # MOV,  THEN,  THEN, ;
\ SCAN and SKIP ( a u c -- a' u' ): step W along the string (T characters left)
\ until the character at W, compared with the delimiter in R0, satisfies cond
\ (EQ: the first c; NE: the first character not c), or the string ends
: SCAN-LOOP, ( cond -- )
  >r  R0 S )+ MOV,  T S ) MOV,  W 2 S I) MOV,
  BEGIN,
    T TST,  EQ IF,  2 S I) W MOV,  S ) T MOV,  NEXT,  THEN,
    BLANKCHAR,  R3 R0 CMP,  r> IF,  2 S I) W MOV,  S ) T MOV,  NEXT,  THEN,
    W INC,  T DEC,
  AGAIN, ;
\ raise FORTH error n from a CODE word: push n (a push, not a replacement of
\ the top: on an empty stack the top is beyond the MMU's fence at S0) and
\ continue in the thread cell holding THROW's code address
: THROW, ( n -- )
  >r S -) r> # MOV,  IP s" THROW-CELL" label-value # MOV,  NEXT, ;
\ a word access at an odd address: the 11/23 (F-11) would silently use the even
\ address below, so @ ! and friends check and report error -23 themselves
: ?ODD, ( -- )  R0 1 # BIT,  NE IF,  -23 THROW,  THEN, ;
\ R0 = the cell on top of the stack; error -9 unless lo <= R0 <= hi (unsigned)
: ?WITHIN, ( lo hi -- )
  over - >r >r  T R0 MOV,  T r> # SUB,  r> # T CMP,  HI IF,  -9 THROW,  THEN, ;
\ take a branch; every loop passes here, so a runaway push loop is caught
\ (error -3) before the data stack runs over the buffers and the dictionary
: BRANCH, ( -- )
  s" S-LIMIT" label-value # S CMP,
  LO IF,  S s" S0" label-value # MOV,  -3 THROW,  THEN,
  IP IP ) MOV,  NEXT, ;
\ a push of n cells on the return stack would pass DOCOL's margin: error -5,
\ with the return stack put back inside its area for THROW's own calls
: ?RPUSH, ( -- )
  s" R-LIMIT" label-value 40 + # RP CMP,
  LO IF,  RP s" R-LIMIT" label-value 200 + # MOV,  -5 THROW,  THEN, ;
\ the vectors and stubs the kernel lives by: 0-77 (traps, console), 250-253
\ (the MMU abort) and the stubs 1000-1777; 100 up are a program's to set
\ The checks themselves are out of line (prims.fs: STORE-CHECK and
\ RANGE-CHECK, reached by JSR PC), so the stores pay 2 instructions inline
: ?STORE, ( -- )  \ R0 = the address of a word or byte store
  $400 # R0 CMP,  LO IF,  s" STORE-CHECK" label-value @# PC JSR,  THEN, ;
: ?STORE-RANGE, ( -- )  \ W = the first address, T = the length; uses R3
  T TST,  NE IF,  s" RANGE-CHECK" label-value @# PC JSR,  THEN, ;
asm>
