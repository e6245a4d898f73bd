\ forth/kernel/facility.fs: FACILITY and FACILITY EXT (Forth-2012 10) on the
\ DL11 console and the KW11-L line clock (177546: bit 7 MONITOR set by every
\ 60 Hz tick, cleared by writing 0 to it; bit 6 interrupt enable).

: EKEY  ( -- x )  KEY ;  \ FACILITY EXT: a key event is the character
: EKEY?  ( -- f )  KEY? ;  \ FACILITY EXT
: EKEY>CHAR  ( x -- x false | c true )  DUP 256 U< ;  \ FACILITY EXT
: EMIT?  ( -- f )  177564O @ 128 AND 0<> ;  \ FACILITY EXT: DL11 transmitter ready
: CSI  ( -- )  27 EMIT [CHAR] [ EMIT ;  \ a VT100 control sequence starts
: AT-XY  ( u1 u2 -- )  \ FACILITY: column u1, row u2 (0 0 = top left), VT100
  CSI 1+ 0 U.R [CHAR] ; EMIT 1+ 0 U.R [CHAR] H EMIT ;
: PAGE  ( -- )  CSI ." 2J" 0 0 AT-XY ;  \ FACILITY: clear the VT100 screen

\ ---- time ----------------------------------------------------------------------
177546O CONSTANT LKS  ( -- a ) \ KW11-L status register
: TICK-WAIT  ( -- )  \ until the next 60 Hz tick; the interrupt enable is kept
  LKS @ 64 AND LKS !  BEGIN LKS @ 128 AND UNTIL ;
: MS  ( u -- )  \ FACILITY EXT: at least u ms of simulated time, in clock ticks
  ?DUP IF 60 UM* 999 0 D+ 1000 UM/MOD NIP 1+ 0 DO TICK-WAIT LOOP THEN ;
\ TIME&DATE: no clock board, so the date starts at the blocks' date, 1983-04-07
\ 00:00:00, at power-up and advances with the ticks the kernel's own clock
\ handler counts (TICKS: while the clock interrupt is enabled and no servo
\ has vector 100)
TICKS CONSTANT TICKS  ( -- a ) \ ticks counted, a double cell
CREATE MONTH-DAYS  ( -- a )  31 C, 28 C, 31 C, 30 C, 31 C, 30 C, 31 C, 31 C, 30 C, 31 C, 30 C, 31 C,
: MONTH-LENGTH  ( month year -- n )
  3 AND 0= OVER 2 = AND IF DROP 29 ELSE 1- MONTH-DAYS + C@ THEN ;
: NEXT-DAY  ( d m y -- d' m' y' )
  >R SWAP 1+ SWAP  2DUP R@ MONTH-LENGTH > IF NIP 1 SWAP 1+ THEN
  DUP 12 > IF DROP 1 R> 1+ >R THEN  R> ;
: TIME&DATE  ( -- sec min hour day month year )  \ FACILITY EXT
  TICKS 2@ 60 UD/MOD ROT DROP  60 UD/MOD 60 UD/MOD 24 UD/MOD DROP
  >R 7 4 1983 R> 0 ?DO NEXT-DAY LOOP ;

\ ---- structures -----------------------------------------------------------------
: BEGIN-STRUCTURE  ( "name" -- addr 0 )  CREATE HERE 0 0 ,  DOES> @ ;  \ FACILITY EXT
: END-STRUCTURE  ( addr n -- )  SWAP ! ;  \ FACILITY EXT
: +FIELD  ( n1 n2 "name" -- n3 )  CREATE OVER , +  DOES> @ + ;  \ FACILITY EXT
: FIELD:  ( n1 "name" -- n2 )  ALIGNED 2 +FIELD ;  \ FACILITY EXT
: CFIELD:  ( n1 "name" -- n2 )  1 +FIELD ;  \ FACILITY EXT
