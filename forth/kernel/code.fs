\ forth/kernel/code.fs: CODE, END-CODE and ;CODE on the resident assembler
\ (vocabulary ASSEMBLER, forth/asm-target.fs). A CODE body ends with END-CODE
\ or with the next defining word (: CREATE CONSTANT CODE and the words built on
\ them), as block 1008 does; either way the assembler checks it (ASM-END).

VARIABLE CODE-OPEN  ( -- a ) \ true while a CODE body is being assembled
' ASSEMBLER >BODY CONSTANT ASSEMBLER-BODY  ( -- a )
: END-CODE  ( -- )
  0 CODE-OPEN !  CURRENT @ CONTEXT !  ASSEMBLER ASM-END FORTH ;
: ?END-CODE  ( -- )  CODE-OPEN @ IF END-CODE THEN ;
: ASSEMBLE  ( -- )  \ assembler first, operand slots clear, depth remembered
  ASSEMBLER-BODY CONTEXT !  TRUE CODE-OPEN !  ASSEMBLER ASM-START FORTH ;
: CODE  ( "name" -- )  \ header whose code field is the machine code that follows
  ?END-CODE PARSE-NAME HEADER, ASSEMBLE ;
: ;CODE  ( colon-sys -- )  \ children run the code after it with W = body
  ['] (DOES>) ,  5726O ,  4 ?PAIRS  REVEAL  POSTPONE [  0 COLON-LFA !  ASSEMBLE ;
  IMMEDIATE COMPILE-ONLY
: CODE-ERROR  ( -- )  \ after any error: no CODE body open, no stale operand
  0 CODE-OPEN !  ASSEMBLER ASM-RESET FORTH ;
