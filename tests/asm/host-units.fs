\ tests/asm/host-units.fs: assemble corpus units with the assembler loaded before.
\ Units come as  s" forth text" unit  and each prints one line:
\   ok 012700 001234      the words assembled at ORIGIN (octal)
\   error N message       the unit aborted after N words (of earlier instructions)
variable origin  512 origin !            \ 001000 unless told otherwise
: .o ( x -- ) base @ >r 8 base ! 65535 and 0 <# # # # # # # #> type space r> base ! ;
: words. ( -- ) ahere-var @ origin @ ?do i a@ .o 2 +loop ;
: run ( addr u -- ) 2>r start-code-body 2r> evaluate end-code-body ;
: asm-off ( -- ) \ after an error: the assembler off the search order if first
  get-order dup if over assembler-wordlist = if nip 1- set-order exit then then
  set-order ;
: unit ( addr u -- )
  origin @ ahere-var !
  ['] run catch ?dup if
    nip nip asm-off
    ." error " ahere-var @ origin @ - 2/ 0 .r space
    -2 = if "error @ count type else ." (gforth exception)" then
  else ." ok " words. then cr ;
