\ editor.fs: the line editor, vocabulary EDITOR (FORTH-79 style: typing
\ EDITOR makes it the context vocabulary; it chains to FORTH).
\ Every command works on block SCR (set by LIST, N, B, WIPE, COPY); lines
\ are 0..15, 64 characters each. Commands that change the block UPDATE it;
\ FLUSH (or SAVE-BUFFERS) writes it to disk. See forth/EDITOR.md.

VOCABULARY EDITOR
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
: N ( -- ) 1 SCR +! L ;                           \ list the next block
: B ( -- ) -1 SCR +! L ;                          \ list the block before

FORTH DEFINITIONS
