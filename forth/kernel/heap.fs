\ forth/kernel/heap.fs: the MEMORY word set (Forth-2012 14): ALLOCATE FREE RESIZE
\ on a first-fit heap of 4096 bytes that the first ALLOCATE takes from the top of
\ the dictionary space (DICT-END moves down: UNUSED shrinks, HERE stays).
\ A heap block is a cell, its size in bytes (header included, even) with bit 0
\ set while in use, then its data; free neighbours are joined as ALLOCATE walks.

4096 CONSTANT HEAP-SIZE  ( -- u )
VARIABLE HEAP  ( -- a ) \ the heap's first block, 0 until the first ALLOCATE
: HEAP-END  ( -- a )  HEAP @ HEAP-SIZE + ;
: H-SIZE  ( h -- u )  @ -2 AND ;
: H-USED?  ( h -- f )  @ 1 AND ;
: H-NEXT  ( h -- h' )  DUP H-SIZE + ;
: H-NEED  ( u -- u' )  3 + -2 AND ;  \ the data in whole cells, and the header
: H-MERGE  ( h -- )  \ join the free blocks that follow free block h
  BEGIN DUP H-NEXT DUP HEAP-END U< IF DUP H-USED? 0= ELSE FALSE THEN
  WHILE H-SIZE OVER +! REPEAT 2DROP ;
: H-TAKE  ( need h -- a-addr )  \ free h, large enough: split off the rest, mark it
  DUP H-SIZE 2 PICK - DUP 4 < IF DROP NIP ELSE >R 2DUP + R> SWAP ! TUCK ! THEN
  DUP 1 SWAP +!  2+ ;
: HEAP?  ( -- f )  \ the heap exists, taken from the dictionary space if need be
  HEAP @ IF TRUE EXIT THEN  UNUSED HEAP-SIZE U< IF FALSE EXIT THEN
  DICT-END @ HEAP-SIZE - DUP DICT-END !  DUP HEAP !  HEAP-SIZE SWAP !  TRUE ;
: ALLOCATE  ( u -- a-addr ior )  \ MEMORY; ior -59 when no block is large enough
  DUP HEAP-SIZE U< 0= HEAP? 0= OR IF DROP 0 -59 EXIT THEN  H-NEED HEAP @
  BEGIN DUP HEAP-END U< WHILE
    DUP H-USED? 0= IF DUP H-MERGE  2DUP H-SIZE SWAP U< 0= IF H-TAKE 0 EXIT THEN THEN
    H-NEXT
  REPEAT 2DROP 0 -59 ;
: H-BLOCK?  ( a-addr -- h f )  \ the header of an allocated block, and whether it is one
  2- DUP HEAP @ HEAP-END WITHIN IF DUP H-USED? 0<> ELSE FALSE THEN ;
: FREE  ( a-addr -- ior )  \ MEMORY; ior -60 for an address ALLOCATE did not give
  H-BLOCK? IF -1 SWAP +! 0 ELSE DROP -60 THEN ;
: RESIZE  ( a-addr1 u -- a-addr2 ior )  \ MEMORY; on failure a-addr1 and ior -61
  DUP HEAP-SIZE U< 0= IF DROP -61 EXIT THEN
  OVER H-BLOCK? 0= IF 2DROP -61 EXIT THEN
  DUP H-SIZE >R  -1 OVER +!  DUP H-MERGE  \ free it, joined with free neighbours after
  OVER H-NEED OVER H-SIZE U> 0= IF SWAP H-NEED SWAP H-TAKE NIP  R> DROP 0 EXIT THEN
  R> SWAP H-TAKE DROP  \ not in place: back as it was, then a new block
  DUP ALLOCATE ?DUP IF NIP NIP EXIT THEN
  SWAP >R 2DUP R> MOVE  SWAP FREE DROP 0 ;
