\ tests/asm/host-image.fs: a 64 KB target image on the host, and the four words
\ forth/asm.fs assembles through (forth/ASSEMBLER.md).
warnings off
create image 65536 allot
variable ahere-var
: >image ( addr -- c-addr ) 65535 and image + ;   \ target addresses are 16-bit
: A! ( x addr -- ) >r 65535 and dup 255 and r@ >image c! 8 rshift r> 1+ >image c! ;
: A@ ( addr -- x ) dup >image c@ swap 1+ >image c@ 8 lshift or ;
: AHERE ( -- addr ) ahere-var @ ;
: A, ( x -- ) ahere-var @ A! 2 ahere-var +! ;
