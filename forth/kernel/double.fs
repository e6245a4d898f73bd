\ forth/kernel/double.fs: the DOUBLE and DOUBLE EXT word sets (Forth-2012 8)
\ beyond D+ DNEGATE DABS D. D.R (prims.fs, core.fs). A double is lo hi, hi on top.

: 2CONSTANT  ( x1 x2 "name" -- )  CREATE , ,  DOES> 2@ ;  \ DOUBLE
: 2VALUE  ( x1 x2 "name" -- )  2CONSTANT ;  \ DOUBLE EXT (TO stores with 2!)
: 2VARIABLE  ( "name" -- )  CREATE 0 , 0 , ;  \ DOUBLE
: 2LITERAL  ( x1 x2 -- )  SWAP POSTPONE LITERAL POSTPONE LITERAL ;  IMMEDIATE COMPILE-ONLY  \ DOUBLE
: D-  ( d1 d2 -- d )  DNEGATE D+ ;  \ DOUBLE
: D0<  ( d -- f )  NIP 0< ;  \ DOUBLE
: D0=  ( d -- f )  OR 0= ;  \ DOUBLE
: D2*  ( d -- d*2 )  2DUP D+ ;  \ DOUBLE
CODE D2/  ( d -- d/2 )  S ) ASR,  2 S I) ROR,  NEXT,  END-CODE  \ DOUBLE
: D=  ( d1 d2 -- f )  ROT = -ROT = AND ;  \ DOUBLE
: D<  ( d1 d2 -- f )  ROT 2DUP = IF 2DROP U< ELSE SWAP < NIP NIP THEN ;  \ DOUBLE
: DU<  ( ud1 ud2 -- f )  ROT 2DUP = IF 2DROP U< ELSE SWAP U< NIP NIP THEN ;  \ DOUBLE EXT
: D>S  ( d -- n )  DROP ;  \ DOUBLE
: DMAX  ( d1 d2 -- d )  2OVER 2OVER D< IF 2SWAP THEN 2DROP ;  \ DOUBLE
: DMIN  ( d1 d2 -- d )  2OVER 2OVER D< 0= IF 2SWAP THEN 2DROP ;  \ DOUBLE
: M+  ( d n -- d' )  S>D D+ ;  \ DOUBLE
: 2ROT  ( d1 d2 d3 -- d2 d3 d1 )  2>R 2SWAP 2R> 2SWAP ;  \ DOUBLE EXT
\ M*/ through a triple-cell product, so d*n never overflows before the division
: T*  ( ud u -- ut )  TUCK UM* 2>R UM* 0 2R> D+ ;
: T/  ( ut u -- ud )  \ the quotient must fit in a double
  >R  0 R@ UM/MOD DROP  R@ UM/MOD  -ROT R> UM/MOD  NIP SWAP ;
: M*/  ( d1 n1 +n2 -- d2 )  \ DOUBLE: d1*n1/n2, rounded towards zero
  >R  2DUP XOR >R  ABS >R DABS R>  T*  R> R> SWAP >R  T/  R> 0< IF DNEGATE THEN ;
