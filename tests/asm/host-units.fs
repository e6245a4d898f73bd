\ tests/asm/host-units.fs: assemble corpus units with the assembler loaded before.
\ Units come as  s" forth text" unit  and each prints one line:
\   ok 012700 001234      the words assembled at ORIGIN (octal)
\   error N message       the unit aborted after N words (of earlier instructions)
variable origin  512 origin !            \ 001000 unless told otherwise
: .o ( x -- ) base @ >r 8 base ! 65535 and 0 <# # # # # # # #> type space r> base ! ;
: words. ( -- ) ahere-var @ origin @ ?do i a@ .o 2 +loop ;
>asm  : run ( addr u -- ) >asm 2>r asm-start 2r> evaluate asm-end asm> ;  asm>
: unit ( addr u -- )
  origin @ ahere-var !
  ['] run catch ?dup if
    nip nip asm>
    ." error " ahere-var @ origin @ - 2/ 0 .r space
    -2 = if "error @ count type else ." (gforth exception)" then
  else ." ok " words. then cr ;
