\ tests/asm/host-driver.fs: the host assembler on a 64 KB byte image.
warnings off
\ Units come as  s" forth text" unit  and each prints one line:
\   ok 012700 001234      the words assembled at ORIGIN (octal)
\   error <message>       the unit aborted; AHERE must not have moved
create image 65536 allot
variable ahere-var
: A! ( x addr -- ) >r 65535 and dup 255 and r@ image + c! 8 rshift r> 1+ image + c! ;
: A@ ( addr -- x ) dup image + c@ swap 1+ image + c@ 8 lshift or ;
: AHERE ( -- addr ) ahere-var @ ;
: A, ( x -- ) ahere-var @ A! 2 ahere-var +! ;
include ../../forth/asm-host.fs

variable origin  512 origin !            \ 001000 unless told otherwise
: .o ( x -- ) base @ >r 8 base ! 0 <# # # # # # # #> type space r> base ! ;
: words. ( -- ) ahere origin @ ?do i a@ .o 2 +loop ;
>asm  : run ( addr u -- ) >asm 2>r asm-start 2r> evaluate asm-end asm> ;  asm>
: unit ( addr u -- )
  origin @ ahere-var !
  ['] run catch ?dup if
    nip nip asm>
    ." error " ahere origin @ - 2/ 0 .r space
    -2 = if "error @ count type else ." (gforth exception)" then
  else ." ok " words. then cr ;
