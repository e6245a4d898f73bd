( forth/asm.fs: the PDP-11 assembler, destination first.          )
( One source, two bindings: the host metacompiler includes it to   )
( assemble CODE words into the target image, and the kernel gets  )
( it metacompiled as vocabulary ASSEMBLER.  Portable subset only;  )
( the includer defines A, AHERE A@ A! first: forth/ASSEMBLER.md. )
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

( Registers: each records itself as a mode-0 operand.  Every    )
( instruction and mode word is a colon definition, not the child  )
( of a defining word, so that a metacompiler can build them all.  )
: ASM-REG ( n -- ) 0 SWAP ASM-OP! ;
: R0 ( -- ) 0 ASM-REG ;   : R1 ( -- ) 1 ASM-REG ;
: R2 ( -- ) 2 ASM-REG ;   : R3 ( -- ) 3 ASM-REG ;
: R4 ( -- ) 4 ASM-REG ;   : R5 ( -- ) 5 ASM-REG ;
: R6 ( -- ) 6 ASM-REG ;   : R7 ( -- ) 7 ASM-REG ;
: T ( -- ) 1 ASM-REG ;    : W ( -- ) 2 ASM-REG ;
: IP ( -- ) 4 ASM-REG ;   : S ( -- ) 5 ASM-REG ;
: RP ( -- ) 6 ASM-REG ;   : SP ( -- ) 6 ASM-REG ;
: PC ( -- ) 7 ASM-REG ;

( Modes 1-5 turn the latest register into reg-deferred forms. )
: ASM-MODE ( mode -- ) 8 * ASM-BARE + ASM-OP1 ASM-OP2 ASM-LAST ! ;
: ) ( -- ) 1 ASM-MODE ;     ( mode 1: register deferred      )
: )+ ( -- ) 2 ASM-MODE ;    ( mode 2: autoincrement          )
: @)+ ( -- ) 3 ASM-MODE ;   ( mode 3: autoincrement deferred )
: -) ( -- ) 4 ASM-MODE ;    ( mode 4: autodecrement          )
: @-) ( -- ) 5 ASM-MODE ;   ( mode 5: autodecrement deferred )

( Modes 6-7: X R then I-paren; the index X sits just below R. )
: ASM-INDEX ( x mode -- ) 8 * ASM-BARE + 64 +  ( x field )
  DEPTH 1- DUP ASM-D1 ASM-D2 ASM-LAST @ = SWAP 0> AND 0=
  ASM-ERR? ABORT" index must come just before the register"
  ASM-OP1 ASM-OP2 ASM-LAST !  ASM-X1 ASM-X2 ASM-LAST !
  DEPTH ASM-D1 ASM-D2 ASM-LAST ! ;
: I) ( x -- ) 6 ASM-INDEX ;     ( mode 6: indexed        )
: @I) ( x -- ) 7 ASM-INDEX ;    ( mode 7: index deferred )

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
: ASM-2OP ( op -- ) ( destination written )
  2 ASM-OPERANDS ASM-OP1 ASM-?WRITE ASM-DOUBLE ;
: ASM-2OPR ( op -- ) ( destination only read: CMP BIT )
  2 ASM-OPERANDS ASM-DOUBLE ;
: MOV, ( -- ) 4096 ASM-2OP ;      ( 010000 )
: MOVB, ( -- ) 36864 ASM-2OP ;    ( 110000 )
: CMP, ( -- ) 8192 ASM-2OPR ;     ( 020000 )
: CMPB, ( -- ) 40960 ASM-2OPR ;   ( 120000 )
: BIT, ( -- ) 12288 ASM-2OPR ;    ( 030000 )
: BITB, ( -- ) 45056 ASM-2OPR ;   ( 130000 )
: BIC, ( -- ) 16384 ASM-2OP ;     ( 040000 )
: BICB, ( -- ) 49152 ASM-2OP ;    ( 140000 )
: BIS, ( -- ) 20480 ASM-2OP ;     ( 050000 )
: BISB, ( -- ) 53248 ASM-2OP ;    ( 150000 )
: ADD, ( -- ) 24576 ASM-2OP ;     ( 060000 )
: SUB, ( -- ) 57344 ASM-2OP ;     ( 160000 )

( Single operand. )
: ASM-1OP ( op -- ) ( writes its operand )
  1 ASM-OPERANDS ASM-OP1 ASM-?WRITE ASM-SINGLE ;
: ASM-1OPR ( op -- ) ( only reads its operand )
  1 ASM-OPERANDS ASM-SINGLE ;
: CLR, ( -- ) 2560 ASM-1OP ;      ( 005000 )
: CLRB, ( -- ) 35328 ASM-1OP ;    ( 105000 )
: COM, ( -- ) 2624 ASM-1OP ;      ( 005100 )
: COMB, ( -- ) 35392 ASM-1OP ;    ( 105100 )
: INC, ( -- ) 2688 ASM-1OP ;      ( 005200 )
: INCB, ( -- ) 35456 ASM-1OP ;    ( 105200 )
: DEC, ( -- ) 2752 ASM-1OP ;      ( 005300 )
: DECB, ( -- ) 35520 ASM-1OP ;    ( 105300 )
: NEG, ( -- ) 2816 ASM-1OP ;      ( 005400 )
: NEGB, ( -- ) 35584 ASM-1OP ;    ( 105400 )
: ADC, ( -- ) 2880 ASM-1OP ;      ( 005500 )
: ADCB, ( -- ) 35648 ASM-1OP ;    ( 105500 )
: SBC, ( -- ) 2944 ASM-1OP ;      ( 005600 )
: SBCB, ( -- ) 35712 ASM-1OP ;    ( 105600 )
: TST, ( -- ) 3008 ASM-1OPR ;     ( 005700 )
: TSTB, ( -- ) 35776 ASM-1OPR ;   ( 105700 )
: ROR, ( -- ) 3072 ASM-1OP ;      ( 006000 )
: RORB, ( -- ) 35840 ASM-1OP ;    ( 106000 )
: ROL, ( -- ) 3136 ASM-1OP ;      ( 006100 )
: ROLB, ( -- ) 35904 ASM-1OP ;    ( 106100 )
: ASR, ( -- ) 3200 ASM-1OP ;      ( 006200 )
: ASRB, ( -- ) 35968 ASM-1OP ;    ( 106200 )
: ASL, ( -- ) 3264 ASM-1OP ;      ( 006300 )
: ASLB, ( -- ) 36032 ASM-1OP ;    ( 106300 )
: SWAB, ( -- ) 192 ASM-1OP ;      ( 000300 )
: SXT, ( -- ) 3520 ASM-1OP ;      ( 006700 )
: MFPS, ( -- ) 36288 ASM-1OP ;    ( 106700 )
: MTPS, ( -- ) 36096 ASM-1OPR ;   ( 106400 )
: MFPI, ( -- ) 3392 ASM-1OPR ;    ( 006500 )
: MTPI, ( -- ) 3456 ASM-1OP ;     ( 006600 )
: MFPD, ( -- ) 36160 ASM-1OPR ;   ( 106500 )
: MTPD, ( -- ) 36224 ASM-1OP ;    ( 106600 )

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
: MUL, ( -- ) 28672 2 ASM-OPERANDS ASM-EIS ;  ( 070000 )
: ASH, ( -- ) 29696 2 ASM-OPERANDS ASM-EIS ;  ( 072000 )
: ASHC, ( -- ) 30208 2 ASM-OPERANDS ASM-EIS ;  ( 073000 )
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
: ASM-0OP ( op -- ) 0 ASM-OPERANDS A, ;
: HALT, ( -- ) 0 ASM-0OP ;        ( 000000 )
: WAIT, ( -- ) 1 ASM-0OP ;        ( 000001 )
: RTI, ( -- ) 2 ASM-0OP ;         ( 000002 )
: BPT, ( -- ) 3 ASM-0OP ;         ( 000003 )
: IOT, ( -- ) 4 ASM-0OP ;         ( 000004 )
: RESET, ( -- ) 5 ASM-0OP ;       ( 000005 )
: RTT, ( -- ) 6 ASM-0OP ;         ( 000006 )
: MFPT, ( -- ) 7 ASM-0OP ;        ( 000007 )
: NOP, ( -- ) 160 ASM-0OP ;       ( 000240 )
: CLC, ( -- ) 161 ASM-0OP ;       ( 000241 )
: CLV, ( -- ) 162 ASM-0OP ;       ( 000242 )
: CLZ, ( -- ) 164 ASM-0OP ;       ( 000244 )
: CLN, ( -- ) 168 ASM-0OP ;       ( 000250 )
: CCC, ( -- ) 175 ASM-0OP ;       ( 000257 )
: SEC, ( -- ) 177 ASM-0OP ;       ( 000261 )
: SEV, ( -- ) 178 ASM-0OP ;       ( 000262 )
: SEZ, ( -- ) 180 ASM-0OP ;       ( 000264 )
: SEN, ( -- ) 184 ASM-0OP ;       ( 000270 )
: SCC, ( -- ) 191 ASM-0OP ;       ( 000277 )
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
: BR, ( addr -- ) 256 ASM-BRANCH, ;     ( 000400 )
: BNE, ( addr -- ) 512 ASM-BRANCH, ;    ( 001000 )
: BEQ, ( addr -- ) 768 ASM-BRANCH, ;    ( 001400 )
: BGE, ( addr -- ) 1024 ASM-BRANCH, ;   ( 002000 )
: BLT, ( addr -- ) 1280 ASM-BRANCH, ;   ( 002400 )
: BGT, ( addr -- ) 1536 ASM-BRANCH, ;   ( 003000 )
: BLE, ( addr -- ) 1792 ASM-BRANCH, ;   ( 003400 )
: BPL, ( addr -- ) 32768 ASM-BRANCH, ;  ( 100000 )
: BMI, ( addr -- ) 33024 ASM-BRANCH, ;  ( 100400 )
: BHI, ( addr -- ) 33280 ASM-BRANCH, ;  ( 101000 )
: BLOS, ( addr -- ) 33536 ASM-BRANCH, ; ( 101400 )
: BVC, ( addr -- ) 33792 ASM-BRANCH, ;  ( 102000 )
: BVS, ( addr -- ) 34048 ASM-BRANCH, ;  ( 102400 )
: BCC, ( addr -- ) 34304 ASM-BRANCH, ;  ( 103000 )
: BCS, ( addr -- ) 34560 ASM-BRANCH, ;  ( 103400 )
: BHIS, ( addr -- ) 34304 ASM-BRANCH, ; ( 103000 )
: BLO, ( addr -- ) 34560 ASM-BRANCH, ;  ( 103400 )

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
