( forth/asm.fs: the PDP-11 assembler, destination first.          )
( One source, two bindings: the host metacompiler includes it to   )
( assemble CODE words into the target image, and the kernel gets  )
( it metacompiled as vocabulary ASSEMBLER.  Portable subset only;  )
( the includer defines A, AHERE A@ A! first: forth-contract.md.    )
( Numbers are decimal, octal in the comments, because the host     )
( reads this file without the target's trailing-O octal literals.  )
( Syntax and word list: forth/ASSEMBLER.md.                        )

( Operands are recorded in two slots, not left on the data stack: )
( a plain number can then never pass for an operand, and a slot  )
( remembers the stack depth it was made at, so a stray number    )
( between operands is caught.  Slot field: mode*8+reg, +64 when  )
( the operand carries an extra word: index, immediate, address.   )
VARIABLE ASM-#OPS                 ( operands recorded: 0, 1, 2 )
VARIABLE ASM-OP1  VARIABLE ASM-X1  VARIABLE ASM-D1  ( first )
VARIABLE ASM-OP2  VARIABLE ASM-X2  VARIABLE ASM-D2  ( second )
VARIABLE ASM-DEPTH                ( stack depth at ASM-START )

: ASM-RESET ( -- ) 0 ASM-#OPS ! ;
: ASM-ERR? ( flag -- flag ) DUP IF ASM-RESET THEN ;
: ASM-LAST ( a1 a2 -- a ) ASM-#OPS @ 2 = IF SWAP THEN DROP ;

: ASM-OP! ( x field -- ) ( record a new operand )
  ASM-#OPS @ 2 = ASM-ERR? ABORT" : more than two operands"
  1 ASM-#OPS +!  ASM-OP1 ASM-OP2 ASM-LAST !
  ASM-X1 ASM-X2 ASM-LAST !  DEPTH ASM-D1 ASM-D2 ASM-LAST ! ;

: ASM-BARE ( -- reg ) ( the latest operand, a plain register )
  ASM-#OPS @ 0= ASM-ERR? ABORT" : mode word without a register"
  ASM-OP1 ASM-OP2 ASM-LAST @ DUP 7 > ASM-ERR?
  ABORT" : mode word after a mode word" ;

( Registers: each records itself as a mode-0 operand. )
: REG ( n "name" -- ) CREATE , DOES> ( -- ) @ 0 SWAP ASM-OP! ;
0 REG R0  1 REG R1  2 REG R2  3 REG R3
4 REG R4  5 REG R5  6 REG R6  7 REG R7
1 REG T   2 REG W   4 REG IP  5 REG S   6 REG RP  6 REG SP  7 REG PC

( Modes 1-5 turn the latest register into reg-deferred forms. )
: ASM-MODE ( mode "name" -- ) CREATE ,
  DOES> ( -- ) @ 8 * ASM-BARE + ASM-OP1 ASM-OP2 ASM-LAST ! ;
1 ASM-MODE )    ( mode 1: register deferred       )
2 ASM-MODE )+   ( mode 2: autoincrement           )
3 ASM-MODE @)+  ( mode 3: autoincrement deferred  )
4 ASM-MODE -)   ( mode 4: autodecrement           )
5 ASM-MODE @-)  ( mode 5: autodecrement deferred  )

( Modes 6-7: X R then I-paren; the index X sits just below R. )
: ASM-INDEX ( mode "name" -- ) CREATE ,
  DOES> ( x -- ) @ 8 * ASM-BARE + 64 +  ( x field )
  DEPTH 1- DUP ASM-D1 ASM-D2 ASM-LAST @ = SWAP 0> AND 0=
  ASM-ERR? ABORT" : index must come just before the register"
  ASM-OP1 ASM-OP2 ASM-LAST !  ASM-X1 ASM-X2 ASM-LAST !
  DEPTH ASM-D1 ASM-D2 ASM-LAST ! ;
6 ASM-INDEX I)   ( mode 6: indexed               )
7 ASM-INDEX @I)  ( mode 7: index deferred        )

: # ( n -- ) ( immediate operand: mode 2 on PC, n follows )
  DEPTH 1 < ASM-ERR? ABORT" : # needs a number" 87 ASM-OP! ;
: @# ( a -- ) ( absolute operand: mode 3 on PC, a follows )
  DEPTH 1 < ASM-ERR? ABORT" : @# needs an address" 95 ASM-OP! ;

( Checks done before anything is emitted. )
: ASM-OPERANDS ( x n -- x ) ( exactly n operands, none left behind )
  ASM-#OPS @ <> ASM-ERR? ABORT" : wrong number of operands"
  DEPTH 1-
  ASM-#OPS @ 0> IF DUP ASM-D1 @ <> ASM-ERR?
    ABORT" : a number where an operand is expected" THEN
  ASM-#OPS @ 1 > IF DUP ASM-D2 @ <> ASM-ERR?
    ABORT" : a number where an operand is expected" THEN DROP ;
: ASM-F ( slot -- field ) @ 63 AND ;
: ASM-?WRITE ( slot -- ) ( an immediate cannot be written )
  @ 87 = ASM-ERR? ABORT" : immediate operand as destination" ;
: ASM-?REG ( slot -- ) ( register only )
  @ 7 > ASM-ERR? ABORT" : register operand expected" ;
: ASM-?MEM ( slot -- ) ( not a register, not an immediate )
  DUP @ 8 < SWAP @ 87 = OR ASM-ERR?
  ABORT" : memory operand expected" ;

( Emitting: opcode word, then source extra, then destination extra. )
: ASM-X, ( slot xvar -- ) SWAP @ 64 AND IF @ A, ELSE DROP THEN ;
: ASM-DOUBLE ( op -- ) ( source = second operand, dest = first )
  ASM-OP2 ASM-F 64 * OR ASM-OP1 ASM-F OR A,
  ASM-OP2 ASM-X2 ASM-X,  ASM-OP1 ASM-X1 ASM-X,  ASM-RESET ;
: ASM-EMIT ( op slot xvar -- ) ( slot in the low six bits )
  >R >R R@ ASM-F OR A, R> R> ASM-X, ASM-RESET ;
: ASM-SINGLE ( op -- ) ASM-OP1 ASM-X1 ASM-EMIT ;

( Double operand: dst src OP, -- MACRO-11 order reversed. )
: 2OP ( op "name" -- ) CREATE ,
  DOES> ( -- ) @ 2 ASM-OPERANDS ASM-OP1 ASM-?WRITE ASM-DOUBLE ;
: 2OPR ( op "name" -- ) ( destination only read: CMP BIT )
  CREATE , DOES> ( -- ) @ 2 ASM-OPERANDS ASM-DOUBLE ;
 4096 2OP MOV,     36864 2OP MOVB,    ( 010000 110000 )
 8192 2OPR CMP,    40960 2OPR CMPB,   ( 020000 120000 )
12288 2OPR BIT,    45056 2OPR BITB,   ( 030000 130000 )
16384 2OP BIC,     49152 2OP BICB,    ( 040000 140000 )
20480 2OP BIS,     53248 2OP BISB,    ( 050000 150000 )
24576 2OP ADD,     57344 2OP SUB,     ( 060000 160000 )

( Single operand. )
: 1OP ( op "name" -- ) ( writes its operand )
  CREATE , DOES> ( -- ) @ 1 ASM-OPERANDS ASM-OP1 ASM-?WRITE ASM-SINGLE ;
: 1OPR ( op "name" -- ) ( only reads its operand )
  CREATE , DOES> ( -- ) @ 1 ASM-OPERANDS ASM-SINGLE ;
 2560 1OP CLR,     35328 1OP CLRB,    ( 005000 105000 )
 2624 1OP COM,     35392 1OP COMB,    ( 005100 105100 )
 2688 1OP INC,     35456 1OP INCB,    ( 005200 105200 )
 2752 1OP DEC,     35520 1OP DECB,    ( 005300 105300 )
 2816 1OP NEG,     35584 1OP NEGB,    ( 005400 105400 )
 2880 1OP ADC,     35648 1OP ADCB,    ( 005500 105500 )
 2944 1OP SBC,     35712 1OP SBCB,    ( 005600 105600 )
 3008 1OPR TST,    35776 1OPR TSTB,   ( 005700 105700 )
 3072 1OP ROR,     35840 1OP RORB,    ( 006000 106000 )
 3136 1OP ROL,     35904 1OP ROLB,    ( 006100 106100 )
 3200 1OP ASR,     35968 1OP ASRB,    ( 006200 106200 )
 3264 1OP ASL,     36032 1OP ASLB,    ( 006300 106300 )
  192 1OP SWAB,     3520 1OP SXT,     ( 000300 006700 )
36288 1OP MFPS,    36096 1OPR MTPS,   ( 106700 106400 )
 3392 1OPR MFPI,    3456 1OP MTPI,    ( 006500 006600 )
36160 1OPR MFPD,   36224 1OP MTPD,    ( 106500 106600 )

: JMP, ( -- ) ( dst JMP, -- mode 0 would trap )
  64 1 ASM-OPERANDS ASM-OP1 ASM-?MEM ASM-SINGLE ;   ( 000100 )
: JSR, ( -- ) ( dst reg JSR, = JSR reg,dst )
  2048 2 ASM-OPERANDS ASM-OP2 ASM-?REG ASM-OP1 ASM-?MEM   ( 004000 )
  ASM-DOUBLE ;
: RTS, ( -- ) ( reg RTS, )
  128 1 ASM-OPERANDS ASM-OP1 ASM-?REG ASM-SINGLE ;  ( 000200 )

( EIS: reg src MUL, = MUL src,reg.  The register is operand one. )
: ASM-EIS ( op -- ) ( check, then emit reg and source )
  ASM-OP1 ASM-?REG ASM-OP1 ASM-F 64 * OR ASM-OP2 ASM-X2 ASM-EMIT ;
: EIS ( op "name" -- ) CREATE , DOES> ( -- ) @ 2 ASM-OPERANDS ASM-EIS ;
28672 EIS MUL,   29696 EIS ASH,   30208 EIS ASHC,  ( 070000 072000 073000 )
: DIV, ( -- ) ( the quotient/remainder pair needs an even register )
  29184 2 ASM-OPERANDS ASM-OP1 ASM-?REG            ( 071000 )
  ASM-OP1 @ 1 AND ASM-ERR? ABORT" : DIV, needs an even register"
  ASM-EIS ;
: XOR, ( -- ) ( dst reg XOR, = XOR reg,dst )
  30720 2 ASM-OPERANDS ASM-OP2 ASM-?REG ASM-OP1 ASM-?WRITE  ( 074000 )
  ASM-DOUBLE ;
: SOB, ( addr -- ) ( addr reg SOB, : back to addr, 0..63 words )
  32256 1 ASM-OPERANDS ASM-OP1 ASM-?REG ASM-OP1 ASM-F 64 * OR ( 077000 )
  SWAP AHERE 2 + SWAP - DUP 1 AND ASM-ERR? ABORT" : odd SOB, target"
  2/ DUP 0 < OVER 63 > OR ASM-ERR? ABORT" : SOB, target out of range"
  OR A, ASM-RESET ;

( Operand-less instructions and those with a number field. )
: 0OP ( op "name" -- ) CREATE , DOES> ( -- ) @ 0 ASM-OPERANDS A, ;
  0 0OP HALT,    1 0OP WAIT,    2 0OP RTI,     3 0OP BPT,
  4 0OP IOT,     5 0OP RESET,   6 0OP RTT,     7 0OP MFPT,
160 0OP NOP,   161 0OP CLC,   162 0OP CLV,   164 0OP CLZ,  ( 240 241 242 244 )
168 0OP CLN,   175 0OP CCC,   177 0OP SEC,   178 0OP SEV,  ( 250 257 261 262 )
180 0OP SEZ,   184 0OP SEN,   191 0OP SCC,                  ( 264 270 277 )
: ASM-NUM, ( n max op -- ) ( op with n in its low bits, 0..max )
  >R OVER < OVER 0 < OR ASM-ERR? ABORT" : number out of range"
  R> 0 ASM-OPERANDS OR A, ;
: EMT, ( n -- ) 255 34816 ASM-NUM, ;   ( 104000 )
: TRAP, ( n -- ) 255 35072 ASM-NUM, ;  ( 104400 )
: MARK, ( n -- ) 63 3328 ASM-NUM, ;    ( 006400 )

( Conditions: the branch opcode taken when the condition holds. )
  768 CONSTANT EQ    512 CONSTANT NE    ( 001400 001000 )
33024 CONSTANT MI  32768 CONSTANT PL    ( 100400 100000 )
34560 CONSTANT CS  34304 CONSTANT CC    ( 103400 103000 )
34048 CONSTANT VS  33792 CONSTANT VC    ( 102400 102000 )
 1280 CONSTANT LT   1024 CONSTANT GE    ( 002400 002000 )
 1792 CONSTANT LE   1536 CONSTANT GT    ( 003400 003000 )
33280 CONSTANT HI  33536 CONSTANT LOS   ( 101000 101400 )
34304 CONSTANT HIS 34560 CONSTANT LO    ( 103000 103400 )

( Branch offsets: words from the word after the branch, -128..127. )
: ASM-OFFSET ( target from -- off ) ( from = address of the branch )
  OVER 1 AND ASM-ERR? ABORT" : odd branch target"
  2 + - 2/ DUP -128 < OVER 127 > OR ASM-ERR?
  ABORT" : branch out of range" 255 AND ;
: ASM-BRANCH, ( addr op -- ) ( emit op branching to addr )
  0 ASM-OPERANDS SWAP AHERE ASM-OFFSET OR A, ;
: BRANCH ( op "name" -- ) CREATE , DOES> ( addr -- ) @ ASM-BRANCH, ;
  256 BRANCH BR,    ( 000400 )
  512 BRANCH BNE,     768 BRANCH BEQ,    ( 001000 001400 )
 1024 BRANCH BGE,    1280 BRANCH BLT,    ( 002000 002400 )
 1536 BRANCH BGT,    1792 BRANCH BLE,    ( 003000 003400 )
32768 BRANCH BPL,   33024 BRANCH BMI,    ( 100000 100400 )
33280 BRANCH BHI,   33536 BRANCH BLOS,   ( 101000 101400 )
33792 BRANCH BVC,   34048 BRANCH BVS,    ( 102000 102400 )
34304 BRANCH BCC,   34560 BRANCH BCS,    ( 103000 103400 )
34304 BRANCH BHIS,  34560 BRANCH BLO,    ( 103000 103400 )

( Structured control.  Stack entries carry a tag so that a THEN, )
( without IF, or an UNTIL, without BEGIN, is caught.             )
-5711 CONSTANT ASM-IF-TAG       -5712 CONSTANT ASM-BEGIN-TAG
: ASM-?COND ( cond -- cond ) ( one of the 14 conditional branches )
  DEPTH 1 < ASM-ERR? ABORT" : condition expected (EQ NE MI PL ...)"
  DUP 30975 AND OVER 34560 AND 512 < OR ASM-ERR?   ( 074377 103400 )
  ABORT" : condition expected (EQ NE MI PL ...)" ;
: ASM-UNPAIRED ( x tag expected -- x tag flag )
  DEPTH 3 < IF DROP -1 ELSE OVER <> THEN ;
: ASM-PATCH ( target b -- ) ( resolve the forward branch at b )
  DUP >R ASM-OFFSET R@ A@ OR R> A! ;

: IF, ( cond -- b tag ) ( branch over when the condition fails )
  ASM-?COND 0 ASM-OPERANDS 256 XOR AHERE SWAP A, ASM-IF-TAG ;
: THEN, ( b tag -- )
  ASM-IF-TAG ASM-UNPAIRED ASM-ERR? ABORT" : THEN, without IF,"
  DROP 0 ASM-OPERANDS AHERE SWAP ASM-PATCH ;
: ELSE, ( b tag -- b2 tag )
  ASM-IF-TAG ASM-UNPAIRED ASM-ERR? ABORT" : ELSE, without IF,"
  DROP 0 ASM-OPERANDS  AHERE 2 + OVER ASM-OFFSET DROP ( in range? )
  AHERE 256 A, ( b b2 ) SWAP AHERE SWAP ASM-PATCH ASM-IF-TAG ;
: BEGIN, ( -- b tag ) AHERE 0 ASM-OPERANDS ASM-BEGIN-TAG ;
: UNTIL, ( b tag cond -- ) ( loop back while the condition fails )
  ASM-?COND >R ASM-BEGIN-TAG ASM-UNPAIRED R> SWAP ASM-ERR?
  ABORT" : UNTIL, without BEGIN," SWAP DROP 256 XOR ASM-BRANCH, ;
: END, ( b tag cond -- ) UNTIL, ;
: AGAIN, ( b tag -- )
  ASM-BEGIN-TAG ASM-UNPAIRED ASM-ERR? ABORT" : AGAIN, without BEGIN,"
  DROP 256 ASM-BRANCH, ;
: WHILE, ( b tag cond -- b tag b2 tag2 )
  ASM-?COND >R ASM-BEGIN-TAG ASM-UNPAIRED R> SWAP ASM-ERR?
  ABORT" : WHILE, without BEGIN," IF, ;
: REPEAT, ( b tag b2 tag2 -- )
  ASM-IF-TAG ASM-UNPAIRED ASM-ERR? ABORT" : REPEAT, without WHILE,"
  DROP >R ASM-BEGIN-TAG ASM-UNPAIRED ASM-ERR?
  ABORT" : REPEAT, without BEGIN," DROP R>   ( b b2 )
  AHERE 2 + OVER ASM-OFFSET DROP ( forward part in range? )
  SWAP 256 ASM-BRANCH,  AHERE SWAP ASM-PATCH ;

: NEXT, ( -- ) IP @)+ JMP, ;   ( JMP @ [R4]+ = 000134 )

( CODE and END-CODE of the includer call these around a body. )
: ASM-START ( -- ) ASM-RESET DEPTH ASM-DEPTH ! ;
: ASM-END ( -- ) ( nothing pending, every structure closed )
  ASM-#OPS @ ASM-ERR? ABORT" : operand without an instruction"
  DEPTH ASM-DEPTH @ <> ASM-ERR?
  ABORT" : unbalanced structure or stray number in CODE" ;
