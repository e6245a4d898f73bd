\ tests/asm/sixteen.fs: 16-bit cell arithmetic on the 64-bit host, to run
\ forth/asm.fs as the PDP-11 will (signed comparisons of values >= 100000 octal).
\ Load before an asm.fs whose literals are already 16-bit (host_asm.py makes
\ that copy); these words come first in the search order while it is included.
: s16 ( n -- n' ) 65535 and dup 32767 > if 65536 - then ;
wordlist constant sixteen-wordlist
get-current sixteen-wordlist set-current
: + ( a b -- a+b ) + s16 ;
: - ( a b -- a-b ) - s16 ;
: * ( a b -- a*b ) * s16 ;
: 1- ( a -- a-1 ) 1- s16 ;
: AHERE ( -- addr ) AHERE s16 ;
: A@ ( addr -- x ) A@ s16 ;
set-current
get-order sixteen-wordlist swap 1+ set-order
