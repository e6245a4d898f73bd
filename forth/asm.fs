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
( Each VARIABLE: -- addr. )
VARIABLE ASM-#OPS                 ( operands recorded: 0, 1, 2 )
VARIABLE ASM-OP1  VARIABLE ASM-X1  VARIABLE ASM-D1  ( first )
VARIABLE ASM-OP2  VARIABLE ASM-X2  VARIABLE ASM-D2  ( second )
VARIABLE ASM-DEPTH                ( stack depth at ASM-START )

: ASM-RESET ( -- ) 0 ASM-#OPS ! ;
: ASM-ERR? ( flag -- flag ) DUP IF ASM-RESET THEN ;
: ASM-LAST ( a1 a2 -- a ) ASM-#OPS @ 2 = IF SWAP THEN DROP ;

: ASM-OP! ( x field -- ) ( record a new operand )
  ASM-#OPS @ 2 = ASM-ERR? ABORT" more than two operands"
  1 ASM-#OPS +!  ASM-OP1 ASM-OP2 ASM-LAST !
  ASM-X1 ASM-X2 ASM-LAST !  DEPTH ASM-D1 ASM-D2 ASM-LAST ! ;

: ASM-BARE ( -- reg ) ( the latest operand, a plain register )
  ASM-#OPS @ 0= ASM-ERR? ABORT" mode word without a register"
  ASM-OP1 ASM-OP2 ASM-LAST @ DUP 7 > ASM-ERR?
  ABORT" mode word after a mode word" ;

( Registers: each records itself as a mode-0 operand. )
: ASM-REG ( n "name" -- ) CREATE , DOES> ( -- ) @ 0 SWAP ASM-OP! ;
0 ASM-REG R0  1 ASM-REG R1  2 ASM-REG R2  3 ASM-REG R3
4 ASM-REG R4  5 ASM-REG R5  6 ASM-REG R6  7 ASM-REG R7
1 ASM-REG T   2 ASM-REG W   4 ASM-REG IP  5 ASM-REG S
6 ASM-REG RP  6 ASM-REG SP  7 ASM-REG PC

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
  ASM-ERR? ABORT" index must come just before the register"
  ASM-OP1 ASM-OP2 ASM-LAST !  ASM-X1 ASM-X2 ASM-LAST !
  DEPTH ASM-D1 ASM-D2 ASM-LAST ! ;
6 ASM-INDEX I)   ( mode 6: indexed               )
7 ASM-INDEX @I)  ( mode 7: index deferred        )

: # ( n -- ) ( immediate operand: mode 2 on PC, n follows )
  DEPTH 1 < ASM-ERR? ABORT" # needs a number" 87 ASM-OP! ;
: @# ( a -- ) ( absolute operand: mode 3 on PC, a follows )
  DEPTH 1 < ASM-ERR? ABORT" @# needs an address" 95 ASM-OP! ;

( Checks done before anything is emitted. )
: ASM-OPERANDS ( x n -- x ) ( exactly n operands, none left behind )
  ASM-#OPS @ <> ASM-ERR? ABORT" wrong number of operands"
  DEPTH 1-
  ASM-#OPS @ 0> IF DUP ASM-D1 @ <> ASM-ERR?
    ABORT" a number where an operand is expected" THEN
  ASM-#OPS @ 1 > IF DUP ASM-D2 @ <> ASM-ERR?
    ABORT" a number where an operand is expected" THEN DROP ;
: ASM-F ( slot -- field ) @ 63 AND ;
: ASM-?WRITE ( slot -- ) ( an immediate cannot be written )
  @ 87 = ASM-ERR? ABORT" immediate operand as destination" ;
: ASM-?REG ( slot -- ) ( register only )
  @ 7 > ASM-ERR? ABORT" register operand expected" ;
: ASM-?MEM ( slot -- ) ( not a register, not an immediate )
  DUP @ 8 < SWAP @ 87 = OR ASM-ERR?
  ABORT" memory operand expected" ;

( Emitting: opcode word, then source extra, then destination extra. )
: ASM-X, ( slot xvar -- ) SWAP @ 64 AND IF @ A, ELSE DROP THEN ;
: ASM-DOUBLE ( op -- ) ( source = second operand, dest = first )
  ASM-OP2 ASM-F 64 * OR ASM-OP1 ASM-F OR A,
  ASM-OP2 ASM-X2 ASM-X,  ASM-OP1 ASM-X1 ASM-X,  ASM-RESET ;
: ASM-EMIT ( op slot xvar -- ) ( slot in the low six bits )
  >R >R R@ ASM-F OR A, R> R> ASM-X, ASM-RESET ;
: ASM-SINGLE ( op -- ) ASM-OP1 ASM-X1 ASM-EMIT ;

( Double operand: dst src OP, -- MACRO-11 order reversed. )
: ASM-2OP ( op "name" -- ) CREATE ,
  DOES> ( -- ) @ 2 ASM-OPERANDS ASM-OP1 ASM-?WRITE ASM-DOUBLE ;
: ASM-2OPR ( op "name" -- ) ( destination only read: CMP BIT )
  CREATE , DOES> ( -- ) @ 2 ASM-OPERANDS ASM-DOUBLE ;
 4096 ASM-2OP MOV,     36864 ASM-2OP MOVB,    ( 010000 110000 )
 8192 ASM-2OPR CMP,    40960 ASM-2OPR CMPB,   ( 020000 120000 )
12288 ASM-2OPR BIT,    45056 ASM-2OPR BITB,   ( 030000 130000 )
16384 ASM-2OP BIC,     49152 ASM-2OP BICB,    ( 040000 140000 )
20480 ASM-2OP BIS,     53248 ASM-2OP BISB,    ( 050000 150000 )
24576 ASM-2OP ADD,     57344 ASM-2OP SUB,     ( 060000 160000 )

( Single operand. )
: ASM-1OP ( op "name" -- ) ( writes its operand )
  CREATE , DOES> ( -- ) @ 1 ASM-OPERANDS ASM-OP1 ASM-?WRITE ASM-SINGLE ;
: ASM-1OPR ( op "name" -- ) ( only reads its operand )
  CREATE , DOES> ( -- ) @ 1 ASM-OPERANDS ASM-SINGLE ;
 2560 ASM-1OP CLR,     35328 ASM-1OP CLRB,    ( 005000 105000 )
 2624 ASM-1OP COM,     35392 ASM-1OP COMB,    ( 005100 105100 )
 2688 ASM-1OP INC,     35456 ASM-1OP INCB,    ( 005200 105200 )
 2752 ASM-1OP DEC,     35520 ASM-1OP DECB,    ( 005300 105300 )
 2816 ASM-1OP NEG,     35584 ASM-1OP NEGB,    ( 005400 105400 )
 2880 ASM-1OP ADC,     35648 ASM-1OP ADCB,    ( 005500 105500 )
 2944 ASM-1OP SBC,     35712 ASM-1OP SBCB,    ( 005600 105600 )
 3008 ASM-1OPR TST,    35776 ASM-1OPR TSTB,   ( 005700 105700 )
 3072 ASM-1OP ROR,     35840 ASM-1OP RORB,    ( 006000 106000 )
 3136 ASM-1OP ROL,     35904 ASM-1OP ROLB,    ( 006100 106100 )
 3200 ASM-1OP ASR,     35968 ASM-1OP ASRB,    ( 006200 106200 )
 3264 ASM-1OP ASL,     36032 ASM-1OP ASLB,    ( 006300 106300 )
  192 ASM-1OP SWAB,     3520 ASM-1OP SXT,     ( 000300 006700 )
36288 ASM-1OP MFPS,    36096 ASM-1OPR MTPS,   ( 106700 106400 )
 3392 ASM-1OPR MFPI,    3456 ASM-1OP MTPI,    ( 006500 006600 )
36160 ASM-1OPR MFPD,   36224 ASM-1OP MTPD,    ( 106500 106600 )

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
: ASM-EIS-OP ( op "name" -- )
  CREATE , DOES> ( -- ) @ 2 ASM-OPERANDS ASM-EIS ;
28672 ASM-EIS-OP MUL,                  ( 070000 )
29696 ASM-EIS-OP ASH,  30208 ASM-EIS-OP ASHC,  ( 072000 073000 )
: DIV, ( -- ) ( the quotient/remainder pair needs an even register )
  29184 2 ASM-OPERANDS ASM-OP1 ASM-?REG            ( 071000 )
  ASM-OP1 @ 1 AND ASM-ERR? ABORT" DIV, needs an even register"
  ASM-EIS ;
: XOR, ( -- ) ( dst reg XOR, = XOR reg,dst )
  30720 2 ASM-OPERANDS ASM-OP2 ASM-?REG ASM-OP1 ASM-?WRITE  ( 074000 )
  ASM-DOUBLE ;
: SOB, ( addr -- ) ( addr reg SOB, : back to addr, 0..63 words )
  32256 1 ASM-OPERANDS ASM-OP1 ASM-?REG ASM-OP1 ASM-F 64 * OR ( 077000 )
  SWAP AHERE 2 + SWAP - DUP 1 AND ASM-ERR? ABORT" odd SOB, target"
  2/ DUP 0 < OVER 63 > OR ASM-ERR? ABORT" SOB, target out of range"
  OR A, ASM-RESET ;

( Operand-less instructions and those with a number field. )
: ASM-0OP ( op "name" -- ) CREATE , DOES> ( -- ) @ 0 ASM-OPERANDS A, ;
  0 ASM-0OP HALT,   1 ASM-0OP WAIT,   2 ASM-0OP RTI,    3 ASM-0OP BPT,
  4 ASM-0OP IOT,    5 ASM-0OP RESET,  6 ASM-0OP RTT,    7 ASM-0OP MFPT,
160 ASM-0OP NOP,  161 ASM-0OP CLC,  162 ASM-0OP CLV,  164 ASM-0OP CLZ,
                   ( 000240 000241 000242 000244 )
168 ASM-0OP CLN,  175 ASM-0OP CCC,  177 ASM-0OP SEC,  178 ASM-0OP SEV,
                   ( 000250 000257 000261 000262 )
180 ASM-0OP SEZ,  184 ASM-0OP SEN,  191 ASM-0OP SCC,
                   ( 000264 000270 000277 )
: ASM-NUM, ( n max op -- ) ( op with n in its low bits, 0..max )
  >R OVER < OVER 0 < OR ASM-ERR? ABORT" number out of range"
  R> 0 ASM-OPERANDS OR A, ;
: EMT, ( n -- ) 255 34816 ASM-NUM, ;   ( 104000 )
: TRAP, ( n -- ) 255 35072 ASM-NUM, ;  ( 104400 )
: MARK, ( n -- ) 63 3328 ASM-NUM, ;    ( 006400 )

( Conditions, each -- cond: the branch opcode taken when it holds. )
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
  OVER 1 AND ASM-ERR? ABORT" odd branch target"
  2 + - 2/ DUP -128 < OVER 127 > OR ASM-ERR?
  ABORT" branch out of range" 255 AND ;
: ASM-BRANCH, ( addr op -- ) ( emit op branching to addr )
  0 ASM-OPERANDS SWAP AHERE ASM-OFFSET OR A, ;
: ASM-BR ( op "name" -- ) CREATE , DOES> ( addr -- ) @ ASM-BRANCH, ;
  256 ASM-BR BR,    ( 000400 )
  512 ASM-BR BNE,     768 ASM-BR BEQ,    ( 001000 001400 )
 1024 ASM-BR BGE,    1280 ASM-BR BLT,    ( 002000 002400 )
 1536 ASM-BR BGT,    1792 ASM-BR BLE,    ( 003000 003400 )
32768 ASM-BR BPL,   33024 ASM-BR BMI,    ( 100000 100400 )
33280 ASM-BR BHI,   33536 ASM-BR BLOS,   ( 101000 101400 )
33792 ASM-BR BVC,   34048 ASM-BR BVS,    ( 102000 102400 )
34304 ASM-BR BCC,   34560 ASM-BR BCS,    ( 103000 103400 )
34304 ASM-BR BHIS,  34560 ASM-BR BLO,    ( 103000 103400 )

( Structured control.  Stack entries carry a tag so that a THEN, )
( without IF, or an UNTIL, without BEGIN, is caught.             )
-5711 CONSTANT ASM-IF-TAG       ( -- tag )
-5712 CONSTANT ASM-BEGIN-TAG    ( -- tag )
: ASM-?COND ( cond -- cond ) ( one of the 14 conditional branches )
  DEPTH 1 < ASM-ERR? ABORT" condition expected (EQ NE MI PL ...)"
  DUP 30975 AND  OVER 34560 AND DUP 0= SWAP 256 = OR  OR ( 074377 103400 )
  ASM-ERR?
  ABORT" condition expected (EQ NE MI PL ...)" ;
: ASM-UNPAIRED ( x tag expected -- x tag flag )
  DEPTH 3 < IF DROP -1 ELSE OVER <> THEN ;
: ASM-PATCH ( target b -- ) ( resolve the forward branch at b )
  DUP >R ASM-OFFSET R@ A@ OR R> A! ;

: IF, ( cond -- b tag ) ( branch over when the condition fails )
  ASM-?COND 0 ASM-OPERANDS 256 XOR AHERE SWAP A, ASM-IF-TAG ;
: THEN, ( b tag -- )
  ASM-IF-TAG ASM-UNPAIRED ASM-ERR? ABORT" THEN, without IF,"
  DROP 0 ASM-OPERANDS AHERE SWAP ASM-PATCH ;
: ELSE, ( b tag -- b2 tag )
  ASM-IF-TAG ASM-UNPAIRED ASM-ERR? ABORT" ELSE, without IF,"
  DROP 0 ASM-OPERANDS  AHERE 2 + OVER ASM-OFFSET DROP ( in range? )
  AHERE 256 A, ( b b2 ) SWAP AHERE SWAP ASM-PATCH ASM-IF-TAG ;
: BEGIN, ( -- b tag ) AHERE 0 ASM-OPERANDS ASM-BEGIN-TAG ;
: UNTIL, ( b tag cond -- ) ( loop back while the condition fails )
  ASM-?COND >R ASM-BEGIN-TAG ASM-UNPAIRED R> SWAP ASM-ERR?
  ABORT" UNTIL, without BEGIN," SWAP DROP 256 XOR ASM-BRANCH, ;
: END, ( b tag cond -- ) UNTIL, ;
: AGAIN, ( b tag -- )
  ASM-BEGIN-TAG ASM-UNPAIRED ASM-ERR? ABORT" AGAIN, without BEGIN,"
  DROP 256 ASM-BRANCH, ;
: WHILE, ( b tag cond -- b tag b2 tag2 )
  ASM-?COND >R ASM-BEGIN-TAG ASM-UNPAIRED R> SWAP ASM-ERR?
  ABORT" WHILE, without BEGIN," IF, ;
: REPEAT, ( b tag b2 tag2 -- )
  ASM-IF-TAG ASM-UNPAIRED ASM-ERR? ABORT" REPEAT, without WHILE,"
  DROP >R ASM-BEGIN-TAG ASM-UNPAIRED ASM-ERR?
  ABORT" REPEAT, without BEGIN," DROP R>   ( b b2 )
  AHERE 2 + OVER ASM-OFFSET DROP ( forward part in range? )
  SWAP 256 ASM-BRANCH,  AHERE SWAP ASM-PATCH ;

: NEXT, ( -- ) IP @)+ JMP, ;   ( JMP @ [R4]+ = 000134 )

( CODE and END-CODE of the includer call these around a body. )
: ASM-START ( -- ) ASM-RESET DEPTH ASM-DEPTH ! ;
: ASM-END ( -- ) ( nothing pending, every structure closed )
  ASM-#OPS @ ASM-ERR? ABORT" operand without an instruction"
  DEPTH ASM-DEPTH @ <> ASM-ERR?
  ABORT" unbalanced structure or stray number in CODE" ;
