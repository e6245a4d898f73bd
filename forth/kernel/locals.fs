\ forth/kernel/locals.fs: the LOCALS word set (Forth-2012 13): {: ... :} (LOCAL)
\ and TO for locals. Loaded last: its IMMEDIATE EXIT shadows the primitive.
\ Run time: a definition's locals are a frame on the return stack, LP points at
\ it: the last one declared by (LOCAL) at LP (the first by {: ... :}), the
\ caller's LP above the frame; (ENDLOCALS) drops it at ; EXIT and DOES>.
\ Compile time: each name is an IMMEDIATE header in LOCALS-AREA, found before
\ every word list while compiling (SEARCH-NAME), that compiles (LOCAL@) offset.

VARIABLE LP  ( -- a ) \ the running definition's locals frame
CODE (LOCALS)  ( x1 .. xn n -- ) ( R: -- lp xn .. x1 )  \ x1 deepest, xn at LP
  R0 S )+ MOV,  T R0 MOV,  T T ADD,  T S ADD,  W T MOV,  \ T, W: past the n values
  RP -) ' LP >BODY @# MOV,
  BEGIN,  R0 TST,  NE WHILE,  RP -) T -) MOV,  R0 DEC,  REPEAT,
  S W MOV,  ' LP >BODY @# RP MOV,  NEXT,  END-CODE  COMPILE-ONLY
CODE (LOCAL@)  ( -- x )  \ the local at the offset that follows in the thread
  R0 IP )+ MOV,  R0 ' LP >BODY @# ADD,  S -) R0 ) MOV,  NEXT,  END-CODE  COMPILE-ONLY
CODE (LOCAL!)  ( x -- )
  R0 IP )+ MOV,  R0 ' LP >BODY @# ADD,  R0 ) S )+ MOV,  NEXT,  END-CODE  COMPILE-ONLY
CODE (ENDLOCALS)  ( -- ) ( R: lp x*n -- )  \ the frame's size in bytes follows
  RP IP )+ ADD,  ' LP >BODY @# RP )+ MOV,  NEXT,  END-CODE  COMPILE-ONLY

16 CONSTANT MAX-LOCALS  ( -- n )
VARIABLE #LOCALS-IN-USE  ( -- a ) \ locals of the definition being compiled
VARIABLE LOCALS-DONE  ( -- a ) \ true once their frame is compiled
\ their names, as headers: in LOCALS-AREA, LOCALS-SIZE bytes (memory.fs)
VARIABLE LOCALS-HERE  ( -- a ) \ next free byte of LOCALS-AREA
: LOCALS-CLEAR  ( -- )  0 #LOCALS-IN-USE !  0 LOCALS-DONE !  LOCALS-AREA LOCALS-HERE ! ;
: LOCALS-LEAVE,  ( -- )  \ compile the dropping of the frame, if there is one
  LOCALS-DONE @ IF ['] (ENDLOCALS) ,  #LOCALS-IN-USE @ 2* , THEN ;
: COMPILE-LOCAL  ( offset -- )  ['] (LOCAL@) , , ;
LABEL LOCAL-DOES  ( -- ) \ a local's name, run while compiling: compile its fetch
  4437O , DODOES ,  ' @ , ' COMPILE-LOCAL , ' EXIT ,  END-CODE
: NEXT-LOCAL  ( nfa -- nfa' )  NAME> 6 + ;
: LOCAL-FIND  ( a u -- nfa | 0 )  \ the newest local of that name
  0 LOCALS-AREA BEGIN DUP LOCALS-HERE @ U< WHILE  ( a u found nfa )
    2OVER 2 PICK COUNT 31 AND NAME= IF NIP DUP THEN  NEXT-LOCAL
  REPEAT DROP NIP NIP ;
: LOCAL-HEADER  ( a u k -- )  \ the k-th local's name; its offset is set by LOCALS-FRAME,
  OVER LOCALS-HERE @ + 8 + LOCALS-AREA LOCALS-SIZE + U> ABORT" local names too long"
  DP @ >R  LOCALS-HERE @ DP !
  -ROT  DUP 128 OR C,  HERE OVER ALLOT SWAP CMOVE  ALIGN  JSR-W , LOCAL-DOES , ,
  HERE LOCALS-HERE !  R> DP ! ;
: (LOCAL)  ( a u -- )  \ LOCALS: one more local (the next value), or u = 0: the end
  LOCALS-DONE @ ABORT" locals declared twice in one definition"
  ?DUP IF #LOCALS-IN-USE @ DUP MAX-LOCALS = ABORT" more than 16 locals"
    LOCAL-HEADER  1 #LOCALS-IN-USE +! EXIT THEN
  DROP FALSE LOCALS-FRAME, ;
: LOCALS-FRAME,  ( first-is-deepest -- )  \ offsets into the headers; compile the frame
  >R  0 LOCALS-AREA BEGIN DUP LOCALS-HERE @ U< WHILE  ( k nfa )
    OVER R@ IF #LOCALS-IN-USE @ 1- SWAP - THEN 2*  OVER NAME> 4 + !
    SWAP 1+ SWAP NEXT-LOCAL
  REPEAT 2DROP R> DROP
  #LOCALS-IN-USE @ POSTPONE LITERAL  ['] (LOCALS) ,  TRUE LOCALS-DONE ! ;
: {:  ( "args [| vals] [-- outs] :}" -- )  \ LOCALS EXT
  0  BEGIN PARSE-NAME  ( vals? a u )
    2DUP S" :}" NAME= IF 2DROP DROP TRUE LOCALS-FRAME, EXIT THEN
    2DUP S" --" NAME= IF 2DROP DROP
      BEGIN PARSE-NAME DUP 0= ABORT" :} missing" S" :}" NAME= UNTIL
      TRUE LOCALS-FRAME, EXIT THEN
    2DUP S" |" NAME= IF 2DROP DROP TRUE ELSE
      DUP 0= ABORT" :} missing"
      2 PICK IF 0 POSTPONE LITERAL THEN  \ a val: its place, uninitialised (0)
      #LOCALS-IN-USE @ DUP MAX-LOCALS = ABORT" more than 16 locals"
      LOCAL-HEADER  1 #LOCALS-IN-USE +!
    THEN
  AGAIN ;  IMMEDIATE COMPILE-ONLY
: LOCAL-TO?  ( a u -- f )  \ TO of a local: compile its store
  STATE @ 0= IF 2DROP FALSE EXIT THEN
  LOCAL-FIND ?DUP IF ['] (LOCAL!) ,  NAME> 4 + @ ,  TRUE ELSE FALSE THEN ;
: LOCAL-OPERAND?  ( xt -- f )  \ followed by an offset in the thread (SEE)
  DUP ['] (LOCAL@) = OVER ['] (LOCAL!) = OR SWAP ['] (ENDLOCALS) = OR ;
' EXIT CONSTANT 'EXIT  ( -- xt ) \ the primitive
: EXIT  ( -- )  LOCALS-LEAVE,  'EXIT COMPILE, ;  IMMEDIATE COMPILE-ONLY  \ CORE: the frame too
