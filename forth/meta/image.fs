\ forth/meta/image.fs: the TARGET memory image, kept apart from host memory.
\ 64 KB of PDP-11 address space as a host byte array; little-endian 16-bit cells.
\ Every access is checked: a target word access at an odd address is a
\ metacompiler bug, reported at once rather than written into the image.

$10000 constant tsize
create timage  tsize allot  timage tsize erase
variable tdp          \ target dictionary pointer (HERE of the image)
variable tlimit       \ first byte the dictionary must not reach
$E000 tlimit !        \ 56 KB of RAM below the I/O page

: taddr ( ta -- host-addr )  \ host address of target byte ta
  dup 0 tsize within 0= abort" target address out of range"  timage + ;
: tc@ ( ta -- c )  taddr c@ ;
: tc! ( c ta -- )  >r $FF and r> taddr c! ;
: teven ( ta -- ta )  dup 1 and abort" odd target address for a word access" ;
: t@ ( ta -- x )  teven dup tc@ swap 1+ tc@ 8 lshift or ;
: t! ( x ta -- )  teven >r $FFFF and dup $FF and r@ tc!  8 rshift r> 1+ tc! ;
: there ( -- ta )  tdp @ ;
: tallot ( n -- )
  tdp +!  there tlimit @ u> abort" target image full" ;
: t, ( x -- )  there t!  2 tallot ;
: tc, ( c -- )  there tc!  1 tallot ;
: talign ( -- )  there 1 and tallot ;

\ The assembler's four hooks (forth/ASSEMBLER.md): assemble into the image.
: A, ( x -- )  t, ;
: AHERE ( -- ta )  there ;
: A@ ( ta -- x )  t@ ;
: A! ( x ta -- )  t! ;

\ ---- PDP-11 absolute loader format (build/kernel.lda) ------------------
\ Block: 1 0, byte count (header 6 + data) low high, load address low high,
\ data, checksum byte making the block's byte sum 0 mod 256. A final block
\ with no data carries the start address.
variable lda-fd  variable lda-sum
create lda-b 1 allot
: lda-byte ( c -- )
  $FF and dup lda-sum +!  lda-b c!  lda-b 1 lda-fd @ write-file throw ;
: lda-word ( x -- )  dup lda-byte 8 rshift lda-byte ;
: lda-block ( ta n -- )
  0 lda-sum !  1 lda-byte 0 lda-byte  dup 6 + lda-word  over lda-word
  bounds ?do i tc@ lda-byte loop
  lda-sum @ negate lda-byte ;
: write-lda ( from to start c-addr u -- )  \ image bytes [from,to) + start address
  w/o bin create-file throw lda-fd !
  >r begin 2dup < while
    over 512 + over min  2 pick - >r  over r@ lda-block  swap r> + swap
  repeat 2drop
  r> 0 lda-block
  lda-fd @ close-file throw ;
