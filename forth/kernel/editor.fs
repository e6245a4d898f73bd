\ editor.fs: the line editor, vocabulary EDITOR (FORTH-79 style: typing
\ EDITOR makes it the context vocabulary; it chains to FORTH).
\ Commands: L T P C INS D E S WIPE COPY N B (stack comments below).
\ Every command works on block SCR (set by LIST, N, B, WIPE, COPY); lines
\ are 0..15, 64 characters each. Commands that change the block UPDATE it;
\ FLUSH (or SAVE-BUFFERS) writes it to disk. See forth/EDITOR.md.

VOCABULARY EDITOR  ( -- ) \ TOOLS EXT: make the editor's words visible (immediate)
EDITOR DEFINITIONS

: LINE ( n -- addr ) \ address of line n of block SCR, n checked
   DUP 16 U< 0= IF CR ." line " . TRUE ABORT" lines are 0..15" THEN
   64 * SCR @ BLOCK + ;
: TEXT ( -- addr len ) \ the rest of the input line, at most 64 characters
   SOURCE >IN @ - SWAP >IN @ + SWAP  SOURCE NIP >IN !
   DUP 64 > ABORT" text longer than 64 characters" ;
: SET-LINE ( addr len n -- ) \ line n := the text, blank-padded
   LINE DUP 64 BL FILL SWAP MOVE UPDATE ;
: OPEN-LINE ( n -- ) \ move lines n..14 down one, line 15 is lost
   LINE DUP 64 +  SCR @ BLOCK B/BUF + OVER -  MOVE ;
: L ( -- ) SCR @ LIST ;                          \ list block SCR
: T ( n -- ) DUP LINE SWAP CR 2 U.R SPACE .LINE ;  \ type line n
: P ( n "text" -- ) TEXT ROT SET-LINE ;          \ put: line n := text
: E ( n -- ) 0 0 ROT SET-LINE ;                  \ erase: blank line n
: INS ( n "text" -- ) \ insert text as line n, lines below move down
   TEXT ROT DUP OPEN-LINE SET-LINE ;
: S ( n -- ) DUP OPEN-LINE E ;                   \ spread: insert a blank line
: D ( n -- ) \ delete line n, lines below move up, line 15 becomes blank
   LINE DUP 64 + SWAP  SCR @ BLOCK B/BUF + OVER - 64 -  MOVE  15 E ;
: WIPE ( blk -- ) \ blank block blk, make it SCR
   DUP SCR ! BUFFER B/BUF BL FILL UPDATE ;
: COPY ( from to -- ) \ copy block from to block to, make it SCR
   DUP SCR ! SWAP BLOCK SWAP BUFFER B/BUF MOVE UPDATE ;
\ C: change text inside a line (old^new), so a typo needs no retyping
VARIABLE 'OLD  ( -- a ) \ C: address of the text to replace
VARIABLE #OLD  ( -- a ) \ C: its length
CREATE NEW-LINE  ( -- a ) 64 ALLOT  \ C builds the changed line here
: CARET ( a u -- i ) \ position of the first ^ in the text, or an error
   0 ?DO DUP I + C@ [CHAR] ^ = IF DROP I UNLOOP EXIT THEN LOOP
   DROP TRUE ABORT" use: n C old^new" ;
: FIND-OLD ( addr -- pos ) \ where the old text first stands in the line at addr
   65 #OLD @ - 0 MAX 0 ?DO DUP I + #OLD @ 'OLD @ #OLD @ COMPARE 0=
      IF DROP I UNLOOP EXIT THEN LOOP
   DROP TRUE ABORT" old text not in the line" ;
: SPLICE ( anew unew laddr pos -- a 64 ) \ the line with old at pos made new
   >R NEW-LINE 64 BL FILL  DUP NEW-LINE R@ MOVE
   DUP 64 -BLANKS NIP R@ - #OLD @ - 0 MAX  SWAP R@ + #OLD @ + SWAP
   2SWAP DUP R@ + 3 PICK + 64 > ABORT" changed line longer than 64 characters"
   TUCK NEW-LINE R@ + SWAP MOVE  R> + NEW-LINE + SWAP MOVE  NEW-LINE 64 ;
: C ( n "old^new" -- ) \ change the first old text in line n into the new
   TEXT 2DUP CARET DUP 0= ABORT" use: n C old^new"
   >R OVER 'OLD ! R@ #OLD !  R> 1+ /STRING
   ROT DUP >R LINE DUP FIND-OLD SPLICE R> SET-LINE ;
: N ( -- ) 1 SCR +! L ;                           \ list the next block
: B ( -- ) -1 SCR +! L ;                          \ list the block before

FORTH DEFINITIONS
