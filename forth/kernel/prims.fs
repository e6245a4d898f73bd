\ forth/kernel/prims.fs: code-field handlers, traps, console, primitives.
\ Registers: R0 T=R1 W=R2 R3 scratch; IP=R4; S=R5 data stack (TOS at (S), no
\ cache); RP=R6 return stack = hardware stack. NEXT = JMP @(IP)+.
\ Code fields: colon  JSR IP,@#DOCOL  (pushes IP, IP = thread, then NEXT)
\              others JSR W,@#handler (W = parameter field, old W pushed)

\ DOCOL also guards the return stack: a runaway recursion is error -5 before it
\ can overwrite the data stack and the dictionary below it
LABEL DOCOL  ( -- )  ?RPUSH,  NEXT,  END-CODE
LABEL DOVAR  ( -- a )  S -) W MOV,  RP )+ TST,  NEXT,  END-CODE
LABEL DOCON  ( -- x )  S -) W ) MOV,  RP )+ TST,  NEXT,  END-CODE
\ DOES> code is JSR IP,@#DODOES: return stack = IP, old W; W = body
LABEL DODOES  ( -- a )  S -) W MOV,  RP ) RP )+ MOV,  NEXT,  END-CODE

\ EXIT checks where it returns to: a thread lies in the kernel or the dictionary
\ space, so a cell a program left with >R (a loop index, a count, a negative
\ number) is error -257 instead of a run through data: one unsigned comparison
\ of IP - ORIGIN, 4 instructions more per EXIT (an odd IP inside that range
\ reads the cells from the even address below, as the 11/23 does)
CODE EXIT  ( -- ) ( R: ip -- )  \ CORE
  IP RP )+ MOV,  R0 IP MOV,  R0 ORIGIN # SUB,  LIMIT ORIGIN - # R0 CMP,
  HIS IF,  -257 THROW,  THEN,  NEXT,  END-CODE  COMPILE-ONLY
CODE (LIT)  ( -- x )  S -) IP )+ MOV,  NEXT,  END-CODE
CODE BRANCH  ( -- )  BRANCH,  END-CODE
CODE ?BRANCH  ( f -- )  S )+ TST,  EQ IF,  BRANCH,  THEN,  IP )+ TST,  NEXT,  END-CODE
\ (EXECUTE) runs an xt the kernel took from a header (the interpreter);
\ EXECUTE, which checks that its xt is one, is in quit.fs
CODE (EXECUTE)  ( xt -- )  R0 S )+ MOV,  R0 ) JMP,  END-CODE

\ DO loops. Return stack: leave address, bias = 100000-limit, index+bias.
\ Adding to index+bias overflows (V) exactly when the index crosses the
\ boundary between limit-1 and limit, in either direction (Forth-94 +LOOP).
CODE (DO)  ( limit start -- )
  ?RPUSH,  RP -) IP )+ MOV,  R0 100000O # MOV,  R0 2 S I) SUB,  RP -) R0 MOV,
  R0 S )+ ADD,  S )+ TST,  RP -) R0 MOV,  NEXT,  END-CODE
CODE (?DO)  ( limit start -- )
  S ) 2 S I) CMP,  EQ IF,  S 4 # ADD,  IP IP ) MOV,  NEXT,  THEN,
  ' (DO) @# JMP,  END-CODE
CODE (LOOP)  ( -- )
  RP ) INC,  VS IF,  RP 6 # ADD,  IP )+ TST,  NEXT,  THEN,  BRANCH,
  END-CODE
CODE (+LOOP)  ( n -- )
  RP ) S )+ ADD,  VS IF,  RP 6 # ADD,  IP )+ TST,  NEXT,  THEN,  BRANCH,
  END-CODE
CODE I  ( -- n )  R0 RP ) MOV,  R0 2 RP I) SUB,  S -) R0 MOV,  NEXT,  END-CODE  COMPILE-ONLY  \ CORE
CODE J  ( -- n )  R0 6 RP I) MOV,  R0 10O RP I) SUB,  S -) R0 MOV,  NEXT,  END-CODE  COMPILE-ONLY  \ CORE
CODE LEAVE  ( -- )  RP 4 # ADD,  IP RP )+ MOV,  NEXT,  END-CODE  COMPILE-ONLY  \ CORE
CODE UNLOOP  ( -- )  RP 6 # ADD,  NEXT,  END-CODE  COMPILE-ONLY  \ CORE

\ stack
CODE DUP  ( x -- x x )  S -) S ) MOV,  NEXT,  END-CODE  \ CORE
CODE DROP  ( x -- )  S 2 # ADD,  NEXT,  END-CODE  \ CORE
CODE SWAP  ( a b -- b a )  R0 S ) MOV,  S ) 2 S I) MOV,  2 S I) R0 MOV,  NEXT,  END-CODE  \ CORE
CODE OVER  ( a b -- a b a )  S -) 2 S I) MOV,  NEXT,  END-CODE  \ CORE
CODE ROT  ( a b c -- b c a )  \ CORE
  R0 4 S I) MOV,  4 S I) 2 S I) MOV,  2 S I) S ) MOV,  S ) R0 MOV,  NEXT,  END-CODE
CODE NIP  ( a b -- b )  R0 S )+ MOV,  S ) R0 MOV,  NEXT,  END-CODE  \ CORE EXT
CODE TUCK  ( a b -- b a b )  \ CORE EXT
  R0 S ) MOV,  S ) 2 S I) MOV,  2 S I) R0 MOV,  S -) R0 MOV,  NEXT,  END-CODE
CODE ?DUP  ( x -- 0 | x x )  S ) TST,  NE IF,  S -) S ) MOV,  THEN,  NEXT,  END-CODE  \ CORE
CODE 2DUP  ( a b -- a b a b )  S -) 2 S I) MOV,  S -) 2 S I) MOV,  NEXT,  END-CODE  \ CORE
CODE 2DROP  ( a b -- )  S 4 # ADD,  NEXT,  END-CODE  \ CORE
CODE 2SWAP  ( a b c d -- c d a b )  \ CORE
  R0 S ) MOV,  S ) 4 S I) MOV,  4 S I) R0 MOV,
  R0 2 S I) MOV,  2 S I) 6 S I) MOV,  6 S I) R0 MOV,  NEXT,  END-CODE
CODE 2OVER  ( a b c d -- a b c d a b )  S -) 6 S I) MOV,  S -) 6 S I) MOV,  NEXT,  END-CODE  \ CORE
CODE PICK  ( xu .. x0 u -- xu .. x0 xu )  \ CORE EXT: u beyond the stack: error -4
  T S0 2 - # MOV,  T S SUB,  T ASR,  T S ) CMP,  HIS IF,  -4 THROW,  THEN,
  R0 S ) MOV,  R0 R0 ADD,  R0 S ADD,  S ) 2 R0 I) MOV,  NEXT,  END-CODE
\ >R 2>R (DO) check the return stack's depth as DOCOL does (2 instructions);
\ R> 2R> refuse to pop RP0's guard cell (the return stack is empty), and pop
\ only after the push: a push beyond S0 is aborted by the MMU, whose trap
\ frame would otherwise land on the cell just popped (a CATCH frame's)
CODE >R  ( x -- ) ( R: -- x )  ?RPUSH,  RP -) S )+ MOV,  NEXT,  END-CODE  COMPILE-ONLY  \ CORE
CODE R>  ( -- x ) ( R: x -- )  \ CORE
  RP0 # RP CMP,  HIS IF,  -6 THROW,  THEN,  S -) RP ) MOV,  RP )+ TST,  NEXT,  END-CODE  COMPILE-ONLY
CODE R@  ( -- x ) ( R: x -- x )  S -) RP ) MOV,  NEXT,  END-CODE  COMPILE-ONLY  \ CORE
CODE 2>R  ( a b -- ) ( R: -- a b )  ?RPUSH,  RP -) 2 S I) MOV,  RP -) S ) MOV,  S 4 # ADD,  NEXT,  \ CORE EXT
  END-CODE  COMPILE-ONLY
CODE 2R>  ( -- a b ) ( R: a b -- )  RP0 2 - # RP CMP,  HIS IF,  -6 THROW,  THEN,  S -) 2 RP I) MOV,  S -) RP ) MOV,  RP 4 # ADD,  NEXT,  \ CORE EXT
  END-CODE  COMPILE-ONLY
CODE SP@  ( -- a )  R0 S MOV,  S -) R0 MOV,  NEXT,  END-CODE
\ SP! and RP! refuse a pointer outside their stack (error -9), which would
\ make the next push write the PSW or a bus error push on no memory
CODE SP!  ( a -- )  R0 S ) MOV,  ?ODD,  S-LIMIT S0 ?WITHIN,  S R0 MOV,  NEXT,  END-CODE
CODE RP@  ( -- a )  S -) RP MOV,  NEXT,  END-CODE
CODE RP!  ( a -- )
  R0 S ) MOV,  ?ODD,  R-LIMIT 40 + RP0 ?WITHIN,  S 2 # ADD,  RP R0 MOV,  NEXT,  END-CODE
CODE DEPTH  ( -- n )  R0 S0 # MOV,  R0 S SUB,  R0 ASR,  S -) R0 MOV,  NEXT,  END-CODE  \ CORE

\ arithmetic and logic
CODE +  ( a b -- a+b )  S ) S )+ ADD,  NEXT,  END-CODE  \ CORE
CODE -  ( a b -- a-b )  S ) S )+ SUB,  NEXT,  END-CODE  \ CORE
CODE AND  ( a b -- a&b )  R0 S )+ MOV,  R0 COM,  S ) R0 BIC,  NEXT,  END-CODE  \ CORE
CODE OR  ( a b -- a|b )  S ) S )+ BIS,  NEXT,  END-CODE  \ CORE
CODE XOR  ( a b -- a^b )  R0 S )+ MOV,  S ) R0 XOR,  NEXT,  END-CODE  \ CORE
CODE INVERT  ( x -- ~x )  S ) COM,  NEXT,  END-CODE  \ CORE
CODE NEGATE  ( n -- -n )  S ) NEG,  NEXT,  END-CODE  \ CORE
CODE 1+  ( n -- n+1 )  S ) INC,  NEXT,  END-CODE  \ CORE
CODE 1-  ( n -- n-1 )  S ) DEC,  NEXT,  END-CODE  \ CORE
CODE 2+  ( n -- n+2 )  S ) 2 # ADD,  NEXT,  END-CODE
CODE 2-  ( n -- n-2 )  S ) 2 # SUB,  NEXT,  END-CODE
CODE 2*  ( x -- x*2 )  S ) ASL,  NEXT,  END-CODE  \ CORE
CODE 2/  ( x -- x/2 )  S ) ASR,  NEXT,  END-CODE  \ CORE
\ a count of 16 or more shifts every bit out (as gforth): 0 at once, not a
\ loop of up to 65535 steps for -1 LSHIFT
CODE LSHIFT  ( x u -- x' )  \ CORE
  R0 S )+ MOV,  16 # R0 CMP,  HIS IF,  S ) CLR,  NEXT,  THEN,
  R0 TST,  NE IF,  BEGIN,  S ) ASL,  R0 DEC,  EQ UNTIL,  THEN,  NEXT,  END-CODE
CODE RSHIFT  ( x u -- x' )  \ CORE
  R0 S )+ MOV,  16 # R0 CMP,  HIS IF,  S ) CLR,  NEXT,  THEN,
  R0 TST,  NE IF,  BEGIN,  CLC,  S ) ROR,  R0 DEC,  EQ UNTIL,  THEN,  NEXT,  END-CODE
CODE =  ( a b -- f )  EQ BINCMP,  END-CODE  \ CORE
CODE <>  ( a b -- f )  NE BINCMP,  END-CODE  \ CORE EXT
CODE <  ( a b -- f )  LT BINCMP,  END-CODE  \ CORE
CODE >  ( a b -- f )  GT BINCMP,  END-CODE  \ CORE
CODE U<  ( a b -- f )  LO BINCMP,  END-CODE  \ CORE
CODE U>  ( a b -- f )  HI BINCMP,  END-CODE  \ CORE EXT
CODE 0=  ( x -- f )  EQ UNCMP,  END-CODE  \ CORE
CODE 0<>  ( x -- f )  NE UNCMP,  END-CODE  \ CORE EXT
CODE 0<  ( n -- f )  MI UNCMP,  END-CODE  \ CORE
CODE 0>  ( n -- f )  GT UNCMP,  END-CODE  \ CORE EXT

\ EIS multiply and divide (MUL/DIV on an even register: R0 high, R1 low)
CODE *  ( a b -- a*b )  R0 S )+ MOV,  R0 S ) MUL,  S ) T MOV,  NEXT,  END-CODE  \ CORE
CODE M*  ( a b -- d )  R0 S ) MOV,  R0 2 S I) MUL,  2 S I) T MOV,  S ) R0 MOV,  NEXT,  \ CORE
  END-CODE
CODE UM*  ( u1 u2 -- ud )  \ CORE: signed MUL, then add back what the signs took away
  R0 S ) MOV,  R0 2 S I) MUL,
  S ) TST,  MI IF,  R0 2 S I) ADD,  THEN,
  2 S I) TST,  MI IF,  R0 S ) ADD,  THEN,
  2 S I) T MOV,  S ) R0 MOV,  NEXT,  END-CODE
CODE SM/REM  ( d n -- rem quot )  \ CORE: symmetric: DIV's own rounding
  S ) TST,  EQ IF,  -10 THROW,  THEN,
  R0 2 S I) MOV,  T 4 S I) MOV,  R0 S )+ DIV,  2 S I) T MOV,  S ) R0 MOV,  NEXT,
  END-CODE
CODE UM/MOD  ( ud u -- rem quot )  \ CORE
  S ) TST,  EQ IF,  -10 THROW,  THEN,
  \ EIS DIV is signed: usable when divisor and high word are below 100000 and
  \ the quotient fits (no V); otherwise 16 shift-and-subtract steps
  S ) TST,  PL IF,
    2 S I) TST,  PL IF,
      R0 2 S I) MOV,  T 4 S I) MOV,  R0 S ) DIV,
      VC IF,  S 2 # ADD,  S ) R0 MOV,  2 S I) T MOV,  NEXT,  THEN,
    THEN,
  THEN,
  W S )+ MOV,  R0 S )+ MOV,  T S ) MOV,  R3 16 # MOV,
  BEGIN,
    T ASL,  R0 ROL,
    CS IF,  R0 W SUB,  T INC,
    ELSE,  W R0 CMP,  HIS IF,  R0 W SUB,  T INC,  THEN,
    THEN,
    R3 DEC,
  EQ UNTIL,
  S ) R0 MOV,  S -) T MOV,  NEXT,  END-CODE
CODE D+  ( d1 d2 -- d )  \ DOUBLE
  R0 S )+ MOV,  T S )+ MOV,  2 S I) T ADD,  S ) ADC,  S ) R0 ADD,  NEXT,  END-CODE
CODE DNEGATE  ( d -- -d )  S ) NEG,  2 S I) NEG,  S ) SBC,  NEXT,  END-CODE  \ DOUBLE

\ memory
CODE @  ( a -- x )  R0 S ) MOV,  ?ODD,  S ) R0 ) MOV,  NEXT,  END-CODE  \ CORE
\ STORE-CHECK (R0 below 2000) and RANGE-CHECK (W start, T length, not 0; uses
\ R3), by JSR PC from ?STORE, ?STORE-RANGE,: error -259 for the vectors and
\ stubs the kernel lives by: 0-77 (traps, console), 250-253 (the MMU abort),
\ the stubs 1000-1777; 100 up are a program's to set (block 1008: 100)
LABEL STORE-CHECK
  100O # R0 CMP,  LO IF,  -259 THROW,  THEN,
  1000O # R0 CMP,  HIS IF,  -259 THROW,  THEN,
  R3 R0 MOV,  R3 3 # BIC,  250O # R3 CMP,  EQ IF,  -259 THROW,  THEN,
  PC RTS,  END-CODE
LABEL RANGE-CHECK
  R3 W MOV,  R3 T ADD,  CS IF,  R3 TST,  NE IF,  -259 THROW,  THEN,  THEN,
  2000O # W CMP,  LO IF,
    100O # W CMP,  LO IF,  -259 THROW,  THEN,
    254O # W CMP,
    HIS IF,  1000O # R3 CMP,  HI IF,  -259 THROW,  THEN,
    ELSE,  250O # R3 CMP,  HI IF,  -259 THROW,  THEN,
    THEN,
  THEN,
  PC RTS,  END-CODE
\ stores refuse the kernel's own vectors and stubs (?STORE,: 2 instructions
\ for an address at or above 2000); FILL CMOVE CMOVE> check their range
CODE !  ( x a -- )  R0 S ) MOV,  ?ODD,  ?STORE,  S 2 # ADD,  R0 ) S )+ MOV,  NEXT,  END-CODE  \ CORE
CODE C@  ( a -- c )  R0 S ) MOV,  S ) CLR,  S ) R0 ) MOVB,  NEXT,  END-CODE  \ CORE
CODE C!  ( c a -- )  R0 S )+ MOV,  ?STORE,  T S )+ MOV,  R0 ) T MOVB,  NEXT,  END-CODE  \ CORE
CODE +!  ( n a -- )  R0 S ) MOV,  ?ODD,  ?STORE,  S 2 # ADD,  R0 ) S )+ ADD,  NEXT,  END-CODE  \ CORE
CODE 2@  ( a -- x1 x2 )  R0 S ) MOV,  ?ODD,  S ) 2 R0 I) MOV,  S -) R0 ) MOV,  NEXT,  END-CODE  \ CORE
CODE 2!  ( x1 x2 a -- )  R0 S ) MOV,  ?ODD,  ?STORE,  R0 2 # ADD,  ?STORE,  R0 S ) MOV,  S 2 # ADD,  R0 )+ S )+ MOV,  R0 ) S )+ MOV,  NEXT,  END-CODE  \ CORE
CODE 1SET  ( a -- )  R0 S )+ MOV,  ?STORE,  R0 ) 1 # MOV,  NEXT,  END-CODE
CODE CMOVE  ( src dst n -- )  \ STRING
  T S ) MOV,  W 2 S I) MOV,  ?STORE-RANGE,  T S )+ MOV,  W S )+ MOV,  R0 S )+ MOV,
  T TST,  NE IF,  BEGIN,  W )+ R0 )+ MOVB,  T DEC,  EQ UNTIL,  THEN,  NEXT,  END-CODE
CODE CMOVE>  ( src dst n -- )  \ STRING
  T S ) MOV,  W 2 S I) MOV,  ?STORE-RANGE,  T S )+ MOV,  W S )+ MOV,  R0 S )+ MOV,  W T ADD,  R0 T ADD,
  T TST,  NE IF,  R3 T MOV,  BEGIN,  W -) R0 -) MOVB,  R3 DEC,  EQ UNTIL,  THEN,
  NEXT,  END-CODE
CODE FILL  ( a n c -- )  \ CORE
  T 2 S I) MOV,  W 4 S I) MOV,  ?STORE-RANGE,  R0 S )+ MOV,  T S )+ MOV,  W S )+ MOV,
  T TST,  NE IF,  BEGIN,  W )+ R0 MOVB,  T DEC,  EQ UNTIL,  THEN,  NEXT,  END-CODE

\ parsing helpers: with a blank delimiter any control character is a blank;
\ /STRING and UPC are CODE for the outer interpreter's sake (issue 19: parsing
\ and numbers cost more than the hashed search)
CODE /STRING  ( a u n -- a+n u-n )  \ STRING
  R0 S )+ MOV,  S ) R0 SUB,  2 S I) R0 ADD,  NEXT,  END-CODE
CODE UPC  ( c -- C )  \ a-z upper-cased, any other value as it is
  141O # S ) CMP,  HIS IF,  172O # S ) CMP,  LOS IF,  S ) 40O # SUB,  THEN,  THEN,  NEXT,  END-CODE
CODE SCAN  ( a u c -- a' u' )  \ first c, or the end
  EQ SCAN-LOOP,  END-CODE
CODE SKIP  ( a u c -- a' u' )  \ first character not c, or the end
  NE SCAN-LOOP,  END-CODE

\ The dictionary search's two halves (CODE words WID-FIND SEARCH-ORDER CHAIN in
\ interp.fs). A word list has #chains (32) chains; a name's chain is its upper-cased
\ first character plus twice its length, mod 32 (the metacompiler's theader
\ hashes alike, and so does the harness's kernel_layout.chain_of).
\ CHAIN-OFFSET (JSR PC): R0 := the byte offset of that chain in a word list, for
\ the name at 2(S), length (S) (at least 1)
LABEL CHAIN-OFFSET
  R0 2 S I) MOV,  R0 R0 ) MOVB,
  141O # R0 CMP,  GE IF,  172O # R0 CMP,  LE IF,  R0 40O # SUB,  THEN,  THEN,
  R0 S ) ADD,  R0 S ) ADD,  R0 #chains 1- INVERT # BIC,  R0 R0 ADD,  PC RTS,  END-CODE
\ WALK (JSR PC): W := the name field of the first header from LFA W on (0: none)
\ down its chain whose name is the one at 2(S), length (S), compared
\ case-insensitively; a smudged word never matches (bit 5 stays in the compared
\ length). Z is set when none matched. R0 T R3 IP are used.
LABEL WALK
  W TST,  NE IF,
    BEGIN,  \ a header of another length costs 6 instructions
      R0 2 W I) MOVB,  R0 177700O # BIC,  R0 S ) CMP,
      EQ IF,
        RP -) W MOV,  R3 2 S I) MOV,  IP W MOV,  IP 3 # ADD,
        BEGIN,
          T R3 )+ MOVB,  W IP )+ MOVB,
          T W CMP,  NE IF,
            141O # T CMP,  GE IF,  172O # T CMP,  LE IF,  T 40O # SUB,  THEN,  THEN,
            141O # W CMP,  GE IF,  172O # W CMP,  LE IF,  W 40O # SUB,  THEN,  THEN,
            T W CMP,
          THEN,
        EQ WHILE,
          R0 DEC,
          EQ IF,  W RP )+ MOV,  W 2 # ADD,  PC RTS,  THEN,
        REPEAT,
        W RP )+ MOV,
      THEN,
      W W ) MOV,
    EQ UNTIL,
  THEN,
  PC RTS,  END-CODE

\ console (DL11 at 177560): receive by interrupt into a ring of 511 characters.
\ Flow control as a DL11 and a paper-tape reader did it (docs/console.md, "A
\ paste"): RXINT sends XOFF (DC3) when the ring holds XOFF-MARK characters, KEY
\ sends XON (DC1) when it finds the ring empty; the terminal side stops
\ delivering meanwhile (pdp11-devices/console_pacing.c). A ring that is full all
\ the same drops further characters and counts them (RXLOST): the guard.
\ ^C is not queued: it empties the ring (counted in RXDROP, reported by .LOST)
\ and interrupts whatever runs (a runaway loop) with error -28

\ SEND-CONTROL (JSR PC; the character in T): wait for the transmitter, send, and
\ wait until it is done, so an EMIT this interrupted finds it free again.
LABEL SEND-CONTROL
  BEGIN,  177564O @# 200O # BIT,  NE UNTIL,  177566O @# T MOV,
  BEGIN,  177564O @# 200O # BIT,  NE UNTIL,  PC RTS,  END-CODE
\ KEY's idle step (JSR PC): with the ring empty, WAIT for the next interrupt, so
\ the host can idle (SET CPU IDLE, pdp11-devices/bus/kw11l.c); time still passes
\ by the instruction count. Its layout is fixed: CMP at +0, BNE at +6, WAIT at
\ +8, RTS at +10. A receive interrupt taken at +6 or +8 has already put its
\ character in the ring, so RXINT returns to +10 instead of letting WAIT sleep
\ on it (the ring is tested again by KEY).
LABEL KEY-IDLE
  RXTAIL @# RXHEAD @# CMP,  EQ IF,  WAIT,  THEN,  PC RTS,  END-CODE
LABEL RXINT
  RP -) R0 MOV,  RP -) T MOV,  RP -) W MOV,
  R0 177562O @# MOV,  R0 177600O # BIC,
  3 # R0 CMP,  EQ IF,
    T RXHEAD @# MOV,  T RXTAIL @# SUB,  T RING-MASK INVERT # BIC,  RXDROP @# T ADD,
    RXTAIL @# RXHEAD @# MOV,
    XOFF-HELD @# TST,  NE IF,  XOFF-HELD @# CLR,  T 17 # MOV,  SEND-CONTROL @# PC JSR,  THEN,
    0 # MTPS,  S S0 # MOV,  S -) CLR,  -28 THROW,  THEN,
  W RXHEAD @# MOV,  T W MOV,  T INC,  T RING-MASK INVERT # BIC,
  T RXTAIL @# CMP,
  EQ IF,  RXLOST @# INC,  ELSE,  RING W I) R0 MOVB,  RXHEAD @# T MOV,
    T RXTAIL @# SUB,  T RING-MASK INVERT # BIC,  XOFF-MARK # T CMP,
    HIS IF,  XOFF-HELD @# TST,  EQ IF,
      XOFF-HELD @# INC,  T 19 # MOV,  SEND-CONTROL @# PC JSR,  THEN,  THEN,
  THEN,
  R0 6 RP I) MOV,  R0 KEY-IDLE 6 + # SUB,  2 # R0 CMP,
  LOS IF,  6 RP I) KEY-IDLE 10 + # MOV,  THEN,
  W RP )+ MOV,  T RP )+ MOV,  R0 RP )+ MOV,  RTI,  END-CODE
CODE KEY?  ( -- f )  \ FACILITY
  T CLR,  RXTAIL @# RXHEAD @# CMP,  NE IF,  T DEC,  THEN,  S -) T MOV,  NEXT,  END-CODE
\ While the priority is 4 or more (Disable.Interrupts at the terminal) the DL11
\ cannot interrupt: KEY then polls the receiver and hands a character to RXINT
\ as the interrupt would (PS and PC pushed), so the console never goes deaf.
CODE KEY  ( -- c )  \ CORE
  BEGIN,  RXTAIL @# RXHEAD @# CMP,  EQ WHILE,
    XOFF-HELD @# TST,  NE IF,  XOFF-HELD @# CLR,  T 17 # MOV,  SEND-CONTROL @# PC JSR,  THEN,
    R0 MFPS,  R0 177400O # BIC,  R0 200O # BIT,      \ MFPS extends the sign: PS is 8 bits
    EQ IF,  KEY-IDLE @# PC JSR,
    ELSE,  177560O @# 200O # BIT,  NE IF,  RP -) R0 MOV,  RXINT @# PC JSR,  THEN,
    THEN,
  REPEAT,
  W RXTAIL @# MOV,  S -) CLR,  S ) RING W I) MOVB,
  W INC,  W RING-MASK INVERT # BIC,  RXTAIL @# W MOV,  NEXT,  END-CODE
CODE PRIORITY!  ( n -- )  \ processor priority 0-7
  R0 S )+ MOV,  R0 ASL,  R0 ASL,  R0 ASL,  R0 ASL,  R0 ASL,  R0 MTPS,  NEXT,  END-CODE
CODE EMIT  ( c -- )  \ CORE
  BEGIN,  177564O @# 200O # BIT,  NE UNTIL,  R0 S )+ MOV,  177566O @# R0 MOV,  NEXT,
  END-CODE

