\ disk.fs: the RL02 driver and the block word set (BLOCK BUFFER UPDATE
\ SAVE-BUFFERS EMPTY-BUFFERS FLUSH LOAD THRU --> ;S LIST INDEX SCR).
\
\ RLV12 registers (DEC RLV12 user's guide; SIMH PDP11/pdp11_rl.c):
\   CSR 174400  bit 0 DRDY drive ready; bits 3:1 function; bit 6 IE;
\               bit 7 CRDY controller ready: writing the CSR with CRDY 0
\               starts the function; bits 9:8 drive; errors: bit 10 OPI
\               operation incomplete, 11 DCRC check/data late, 12 HNF header
\               not found, 13 NXM, 14 DE drive error, 15 CE any error.
\   BAR 174402  bus address of the transfer.
\   DAR 174404  read/write: cylinder<<7 | head<<6 | sector;
\               seek: difference<<7 | head<<4 | 4 (towards higher
\               cylinders) | 1; get status: 3, plus 8 to reset drive errors.
\   MPR 174406  before a transfer: minus the word count; after get status:
\               the drive status; after read header: the header word
\               (cylinder<<7 | head<<6 | sector) of the track under the heads.
\ Functions: 2 get status, 3 seek, 4 read header, 5 write data, 6 read data.
\ RL02: 512 cylinders x 2 heads x 40 sectors of 256 bytes = 10 MB.
\ Block n (1024 bytes) = sectors 4n..4n+3: track n/10 (cylinder = track/2,
\ head = track and 1), first sector 4*(n mod 10). A track holds exactly 10
\ blocks, so a block never crosses a track, and the controller (which never
\ switches heads or cylinders within a transfer) moves it in one operation.
\
\ The driver is polled, at the caller's priority (normally 0): BLOCK has
\ to wait for its data anyway and the FORTH has nothing else to run, while
\ the 60 Hz servo interrupt keeps being served during the wait. An
\ interrupt-driven driver would only pay off with a multitasker.

174400O CONSTANT RLCS  ( -- a ) \ control/status register
174402O CONSTANT RLBA  ( -- a ) \ bus address register
174404O CONSTANT RLDA  ( -- a ) \ disk address register
174406O CONSTANT RLMP  ( -- a ) \ multipurpose register
10240 CONSTANT #BLOCKS  ( -- n ) \ blocks on an RL02 (40960 sectors / 4)
1024 CONSTANT B/BUF  ( -- n ) \ bytes per block
VARIABLE #READS  ( -- a ) \ blocks read so far (LRU tests, statistics)
VARIABLE #WRITES  ( -- a ) \ blocks written so far
VARIABLE RL-BLK  ( -- a ) \ block of the transfer under way, for messages
VARIABLE RL-FN  ( -- a ) \ its function: 5 write, 6 read
: RL-THROW ( -- ) RL-FN @ 5 = IF -34 ELSE -33 THEN THROW ; \ write/read error

\ ---- messages ------------------------------------------------------------
: ?.BIT ( x mask c-addr u -- x ) \ print the name when the bit is set
   >R >R OVER AND IF SPACE R> R> TYPE ELSE R> R> 2DROP THEN ;
: .CSR ( csr -- ) \ controller status, octal, then its error bits by name
   ."  CSR=" DUP .OCTAL
   2000O S" incomplete" ?.BIT   4000O S" data-check" ?.BIT
   10000O S" header-not-found" ?.BIT   20000O S" no-memory" ?.BIT
   40000O S" drive-error" ?.BIT  DROP ;
: .DRIVE ( status -- ) \ drive status (MPR after get status), decoded
   ."  drive=" DUP .OCTAL
   DUP 7 AND 5 <> IF ."  not-ready" THEN
   40O S" cover-open" ?.BIT   400O S" select-error" ?.BIT
   1000O S" volume-check" ?.BIT   2000O S" write-gate-error" ?.BIT
   4000O S" spin-error" ?.BIT   10000O S" seek-timeout" ?.BIT
   20000O S" write-locked" ?.BIT   40000O S" head-current-error" ?.BIT
   100000O S" write-data-error" ?.BIT  DROP ;
: .RL-BLOCK ( -- ) \ start of every driver message: which transfer failed
   CR ." RL0 block " RL-BLK @ U. RL-FN @ 5 = IF ." write " ELSE ." read " THEN ;

\ ---- the controller --------------------------------------------------------
: RL-READY? ( -- f ) RLCS @ 201O AND 201O = ;  \ controller and drive ready
: RL-WAIT ( -- ) \ poll until ready; a dead controller is an error, not a hang
   0 BEGIN RL-READY? 0= WHILE 1+ DUP 0= IF
      DROP .RL-BLOCK ." timed out:" RLCS @ .CSR RL-THROW THEN
   REPEAT DROP ;
: RL-DO ( fn -- csr ) 2* RLCS ! RL-WAIT RLCS @ ;  \ run a function on drive 0
: RL-STATUS ( dar -- status ) RLDA ! 2 RL-DO DROP RLMP @ ; \ get status
: RL-FAIL ( csr -- ) \ report a failed function with the drive status, abort
   .RL-BLOCK ." failed:" .CSR 3 RL-STATUS .DRIVE RL-THROW ;
: ?RL-OK ( csr -- ) DUP 0< IF RL-FAIL THEN DROP ;
: RL-CHECK ( write? -- ) \ the drive must be loaded, spinning and, for a write,
   13O RL-STATUS              \ not locked; get status also clears volume check
   DUP 7 AND 5 <> ROT IF OVER 20000O AND OR THEN
   IF .RL-BLOCK ." not ready:" .DRIVE RL-THROW THEN DROP ;
: RL-CYL ( -- cyl ) 4 RL-DO ?RL-OK RLMP @ 7 RSHIFT ; \ read header: where heads are
: RL-DA ( blk -- da ) 10 /MOD 64 * SWAP 4 * + ;  \ track<<6 | first sector
: RL-SEEK ( da -- ) \ move the heads to the cylinder and head of da
   DUP 7 RSHIFT RL-CYL -
   DUP 0< IF NEGATE 7 LSHIFT 1 OR ELSE 7 LSHIFT 5 OR THEN
   SWAP 64 AND IF 16 OR THEN
   RLDA ! 3 RL-DO ?RL-OK ;
: ?BLOCK# ( blk -- blk ) \ a block past the end of the disk is an error
   DUP #BLOCKS U< 0= IF CR ." block " DUP U. ." is past the end of the disk (0.."
      #BLOCKS 1- 0 U.R ." )" -35 THROW THEN ;
: RL-XFER ( addr blk fn -- ) \ fn 5 writes, 6 reads block blk at addr
   DUP RL-FN ! >R ?BLOCK# DUP RL-BLK ! R@ 5 = RL-CHECK
   RL-DA DUP RL-SEEK RLDA ! RLBA ! B/BUF 2/ NEGATE RLMP ! R> RL-DO ?RL-OK ;
: RL-READ ( addr blk -- ) 6 RL-XFER 1 #READS +! ;
: RL-WRITE ( addr blk -- ) 5 RL-XFER 1 #WRITES +! ;

\ ---- block buffers: 4, least recently used first out --------------------
\ The data live in the kernel's BUFFERS area (forth/kernel/memory.fs, above the
\ dictionary); the tables below are in the image, so every boot starts empty.
4 CONSTANT #BUFS  ( -- n ) \ the four-entry tables below follow from it
CREATE BUF-BLK  ( -- a ) -1 , -1 , -1 , -1 ,  \ block in each buffer, -1 = none
CREATE BUF-UPD  ( -- a )  0 ,  0 ,  0 ,  0 ,  \ true when the buffer was UPDATEd
CREATE BUF-MRU  ( -- a )  0 ,  1 ,  2 ,  3 ,  \ buffer numbers, most recent first
CREATE CUR-BLK  ( -- a ) -1 ,   \ the block UPDATE marks, -1 = none
CREATE BUF-SUM  ( -- a )  0 ,  0 ,  0 ,  0 ,  \ an UPDATEd buffer's checksum (SEAL)
: BUF-ADDR ( i -- addr ) B/BUF * BUFFERS + ;
: >BLK ( i -- addr ) 2* BUF-BLK + ;
: >UPD ( i -- addr ) 2* BUF-UPD + ;

\ ---- nothing the program did not write reaches the disk --------------------
\ A program writes a buffer between BLOCK (or BUFFER) and the next BLOCK or
\ BUFFER, and marks it with UPDATE. So an UPDATEd buffer's checksum (with its
\ block number) is taken at UPDATE and again when the next BLOCK or BUFFER
\ ends that window (SEAL): from then on only a wild store can change it. A
\ trap (a run through data, a wild jump: the state the kernel can no longer
\ vouch for) checks every UPDATEd buffer (CHECK-BUFFERS): one that changed is
\ not written; its block keeps what the disk holds and the report says so. A
\ change made after the last UPDATE and before the trap, with no BLOCK call in
\ between, counts as a change too: UPDATE after writing, as is the custom.
CODE CHECKSUM  ( a -- u )  \ of the 1024 bytes at a: Fletcher's two sums, 512 words
  W S ) MOV,  T 512 # MOV,  R0 CLR,  R3 CLR,   \ R0 the sum, R3 the sum of sums
  BEGIN,  R0 W )+ ADD,  R3 R0 ADD,  T DEC,  EQ UNTIL,
  R0 SWAB,  R3 R0 XOR,  S ) R3 MOV,  NEXT,  END-CODE
: >SUM ( i -- addr ) 2* BUF-SUM + ;
: BUF-SUM@ ( i -- u ) DUP BUF-ADDR CHECKSUM SWAP >BLK @ XOR ;
: SEAL ( i -- ) DUP BUF-SUM@ SWAP >SUM ! ;
: SEAL-CURRENT ( -- ) \ the window on the current buffer ends: seal it if UPDATEd
   CUR-BLK @ DUP 0< IF DROP EXIT THEN RESIDENT DUP 0< IF DROP EXIT THEN
   DUP >UPD @ IF SEAL ELSE DROP THEN ;
: CHECK-BUFFERS ( -- ) \ after a trap: an UPDATEd buffer that changed is set aside
   #BUFS 0 DO I >UPD @ IF I BUF-SUM@ I >SUM @ <> IF
      CR ." NOT SAVED: block " I >BLK @ U. ." (changed since its last UPDATE when the trap hit;"
      ."  the disk keeps the block as it was)"
      0 I >UPD !  -1 I >BLK !
   THEN THEN LOOP ;
: TOUCH ( i -- ) \ make buffer i the most recently used
   BUF-MRU BEGIN 2DUP @ <> WHILE 2 + REPEAT
   BEGIN DUP BUF-MRU <> WHILE DUP 2 - @ OVER ! 2 - REPEAT ! ;
: RESIDENT ( blk -- i | -1 ) \ the buffer holding blk, or -1
   #BUFS 0 DO DUP I >BLK @ = IF DROP I UNLOOP EXIT THEN LOOP DROP -1 ;
: WRITE-BACK ( i -- ) \ write buffer i to disk if UPDATEd
   DUP >UPD @ IF DUP BUF-ADDR OVER >BLK @ RL-WRITE 0 OVER >UPD ! THEN DROP ;
: FREE-BUF ( -- i ) \ the least recently used buffer, written back, unassigned
   BUF-MRU #BUFS 1- 2* + @ DUP WRITE-BACK -1 OVER >BLK ! ;
: BUFFER ( blk -- addr ) \ BLOCK: assign a buffer to blk, contents undefined
   SEAL-CURRENT ?BLOCK# DUP RESIDENT DUP 0< IF DROP FREE-BUF THEN
   OVER CUR-BLK ! TUCK >BLK ! DUP TOUCH BUF-ADDR ;
: (BLOCK) ( blk -- addr ) \ BLOCK for SOURCE: leaves the current block alone
   ?BLOCK# BUF-MRU @ DUP >BLK @ 2 PICK = IF NIP BUF-ADDR EXIT THEN DROP
   DUP RESIDENT DUP 0< IF DROP FREE-BUF 2DUP BUF-ADDR SWAP RL-READ THEN
   TUCK >BLK ! DUP TOUCH BUF-ADDR ;   \ (the first line: the most recent, fast)
: BLOCK ( blk -- addr ) \ BLOCK: the buffer holding blk, read if needed; UPDATE's block
   SEAL-CURRENT DUP (BLOCK) SWAP CUR-BLK ! ;
: UPDATE ( -- ) \ BLOCK: mark the block last given by BLOCK or BUFFER as changed
   CUR-BLK @ DUP 0< 0= IF RESIDENT THEN DUP 0< ABORT" UPDATE: no current block"
   TRUE OVER >UPD ! SEAL ;
: SAVE-BUFFERS ( -- ) #BUFS 0 DO I WRITE-BACK LOOP ;  \ BLOCK
: EMPTY-BUFFERS ( -- ) #BUFS 0 DO -1 I >BLK ! 0 I >UPD ! LOOP -1 CUR-BLK ! ;  \ BLOCK EXT
: FLUSH ( -- ) SAVE-BUFFERS EMPTY-BUFFERS ;  \ BLOCK

\ ---- loading ---------------------------------------------------------------
: LOAD ( blk -- ) \ BLOCK: interpret block blk, then continue where we were
   DUP 0= ABORT" block 0 cannot be loaded"
   DUP BLOCK DROP   \ a bad block fails here, source unchanged; UPDATE now marks blk
   BLK @ >R >IN @ >R SRC-ID @ >R  BLK ! 0 >IN ! 0 SRC-ID !
   INTERPRET  R> SRC-ID ! R> >IN ! R> BLK ! ;
: BLOCK-RANGE ( blk1 blk2 -- blk2+1 blk1 ) \ DO limits; blk1 > blk2 is an error
   2DUP U> ABORT" first block after the last" 1+ SWAP ;
: THRU ( blk1 blk2 -- ) BLOCK-RANGE ?DO I LOAD LOOP ;  \ BLOCK EXT
: --> ( -- ) \ continue loading with the next block
   BLK @ 0= ABORT" --> outside a loaded block"  1 BLK +! 0 >IN ! ; IMMEDIATE
: ;S ( -- ) \ interpreting: stop loading this block; compiling: EXIT (fig)
   STATE @ IF POSTPONE EXIT ELSE SOURCE NIP >IN ! THEN ; IMMEDIATE

: .DISK ( -- ) \ the disk and the state of its drive, for the banner
   ." Disk: RL02 on the RLV12 at 174400, blocks 0-" #BLOCKS 1- 0 U.R
   3 RL-STATUS DUP 7 AND 5 <> IF ." , drive not ready (no disk attached?)" THEN
   20000O AND IF ." , write-locked" THEN ." ." ;

\ ---- listing -------------------------------------------------------------
VARIABLE SCR  ( -- a ) \ BLOCK EXT: the block last listed (the editor's block)
: -BLANKS ( addr len -- addr len' ) \ drop trailing blanks and control chars
   BEGIN DUP IF 2DUP + 1- C@ BL > 0= ELSE FALSE THEN WHILE 1- REPEAT ;
: .LINE ( addr -- ) \ type a 64-character line, control characters as blanks
   64 -BLANKS 0 ?DO DUP I + C@ DUP BL 127 WITHIN 0= IF DROP BL THEN EMIT LOOP
   DROP ;
: LIST ( blk -- ) \ BLOCK EXT: show block blk with line numbers, make it SCR
   DUP BLOCK DROP DUP SCR ! CR ." Block " DUP U.
   16 0 DO CR I 2 U.R SPACE DUP BLOCK I 64 * + .LINE LOOP DROP CR ;
: INDEX ( blk1 blk2 -- ) \ the first line of each block blk1..blk2
   BLOCK-RANGE ?DO CR I 5 U.R SPACE I BLOCK .LINE LOOP CR ;
