\ forth/kernel/code.fs: CODE, END-CODE and ;CODE on the resident assembler
\ (vocabulary ASSEMBLER, forth/asm-target.fs). A CODE body ends with END-CODE
\ or with the next defining word (: CREATE CONSTANT CODE and the words built on
\ them), as block 1008 does; either way the assembler checks it (ASM-END).

VARIABLE CODE-OPEN  ( -- a ) \ true while a CODE body is being assembled
VARIABLE CODE-LFA  ( -- a ) \ header of that word: an error discards it whole
: END-CODE  ( -- )  \ ASM-END first: if it fails, the word is still open
  ASSEMBLER ASM-END FORTH  0 CODE-OPEN !  CURRENT @ VOC-CONTEXT ;
: ?END-CODE  ( -- )  CODE-OPEN @ IF END-CODE THEN ;
: ASSEMBLE  ( -- )  \ assembler first, operand slots clear, depth remembered
  ASSEMBLER-BODY VOC-CONTEXT  TRUE CODE-OPEN !  ASSEMBLER ASM-START FORTH ;
: CODE  ( "name" -- )  \ TOOLS EXT: header whose code field is the machine code that follows
  ?END-CODE ALIGN HERE CODE-LFA !  PARSE-NAME HEADER, ASSEMBLE ;
: ;CODE  ( colon-sys -- )  \ TOOLS EXT: children run the code after it with W = body
  ['] (DOES>) ,  5726O ,  4 ?PAIRS  REVEAL  POSTPONE [
  COLON-LFA @ CODE-LFA !  0 COLON-LFA !  ASSEMBLE ;
  IMMEDIATE COMPILE-ONLY
: CODE-ERROR  ( -- )  \ after any error: no CODE word half-assembled, no stale operand
  CODE-OPEN @ IF CODE-LFA @ ?DUP IF UNLINK THEN THEN
  0 CODE-OPEN !  0 CODE-LFA !  ASSEMBLER ASM-RESET FORTH ;
