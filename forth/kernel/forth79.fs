\ forth/kernel/forth79.fs: the last kernel words, read after the resident
\ assembler (forth/asm-target.fs): FORTH-79's tick, and the assembler's reset
\ on every error.

: (')  ( "name" -- xt )  ' ;  \ the parsing tick (Forth-94 '), kept under this name
: '  ( "name" -- xt )  \ FORTH-79: state-smart; in a definition compiles the address
  (') STATE @ IF POSTPONE LITERAL THEN ;  IMMEDIATE
\ Block 1008 writes `' Interrupt.Servo 100O !` inside a colon definition: it must
\ store the code address when Install.Int.Servo runs, not parse then.

\ after an error, no operand half given to the assembler stays pending
ASSEMBLER ' ASM-RESET FORTH ' 'ON-ERROR >BODY t!
