( tests/asm/resident-driver.fs: loaded on the machine from a block.   )
( UNIT{ ... }UNIT assembles one corpus unit at the same place each    )
( time and prints its words in octal after U: on a line of their own. )
VARIABLE UNIT-BASE  VARIABLE UNIT-AT
: UNIT{ ( -- ) UNIT-BASE @ HERE - ALLOT  HERE UNIT-AT !
  ASSEMBLER ASM-START FORTH ;
: }UNIT ( -- ) ASSEMBLER ASM-END FORTH  BASE @ >R OCTAL CR ." U:"
  HERE UNIT-AT @ ?DO I @ U. 2 +LOOP  R> BASE ! ;
: EMITTED? ( -- ) HERE UNIT-AT @ - 2/ . ;
HERE UNIT-BASE !
ASSEMBLER ' ASM-RESET FORTH 'ON-ERROR !
