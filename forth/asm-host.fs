\ forth/asm-host.fs: load forth/asm.fs on gforth into its own wordlist.
\ Before including this file define, visible in the search order:
\   A, ( x -- )  AHERE ( -- addr )  A@ ( addr -- x )  A! ( x addr -- )
\ working on the target image (16-bit words; A, and A! must mask to 16 bits).
\ Afterwards: ASSEMBLER-WORDLIST holds the assembler; >ASM and ASM> put it
\ first in the search order and take it off again; START-CODE-BODY and
\ END-CODE-BODY do that around a CODE body, with the assembler's checks.

wordlist constant assembler-wordlist

: >asm ( -- ) get-order assembler-wordlist swap 1+ set-order ;
: asm> ( -- ) get-order dup 0= abort" asm>: empty search order"
  over assembler-wordlist <> abort" asm>: assembler not first in search order"
  nip 1- set-order ;

get-current assembler-wordlist set-current >asm
include ./asm.fs
asm> set-current

\ Around a CODE body: the assembler first in the search order, operand slots
\ clear, and at the end a check that every structure closed and nothing is left.
: start-code-body ( -- ) >asm [ >asm ] asm-start [ asm> ] ;
: end-code-body ( -- ) asm> [ >asm ] asm-end [ asm> ] ;
