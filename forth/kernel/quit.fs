\ forth/kernel/quit.fs: the outer interpreter, EVALUATE, error reports, QUIT.

S-LIMIT CONSTANT S-LIMIT  ( -- a )
2 ARRAY WHAT  ( -- a ) \ the word being interpreted: address, length
VARIABLE 'ON-ERROR  ( -- a ) \ xt run after every error (0 = none)
CODE ?STACK  ( -- )  \ error -4 below the empty stack, -3 within 8 cells of full
  S0 # S CMP,  HI IF,  -4 THROW,  THEN,  S-LIMIT 16 + # S CMP,  LO IF,  -3 THROW,  THEN,
  NEXT,  END-CODE
\ Control structures typed at the terminal (0 3 DO I . -1 +LOOP): an opening
\ IF BEGIN DO ?DO in interpret state starts a temporary definition, compiled
\ 1 KB below the dictionary's end, not at HERE: what it lays down with , or
\ ALLOT when it runs (CREATE tbl 3 0 DO I , LOOP) goes to HERE as typed
\ outside it would. While it runs the dictionary ends below it (DICT-END), so
\ ALLOT cannot reach it; afterwards the space is free again.
1024 CONSTANT TEMP-ROOM  ( -- n ) \ the temporary definition and PAD's room above HERE
\ (with less free space, 224 bytes above HERE: PAD's 160 and 64 for , and ALLOT)
VARIABLE TEMP-DEPTH  ( -- a ) \ depth+1 when it started, 0 = none
VARIABLE TEMP-START  ( -- a ) \ where its code starts
VARIABLE TEMP-HERE  ( -- a ) \ HERE before it, put back when it runs
VARIABLE TEMP-END  ( -- a ) \ DICT-END before the outermost run, 0 = none runs
VARIABLE TEMP-HEAP  ( -- a ) \ HEAP then: a heap the run created keeps DICT-END
: OPENER?  ( xt -- xt f )
  DUP ['] IF = OVER ['] BEGIN = OR OVER ['] DO = OR OVER ['] ?DO = OR ;
: TEMP-BEGIN  ( xt -- xt )  \ xt is still on the stack: DEPTH counts it (the +1)
  HERE TEMP-HERE !  DICT-END @ TEMP-ROOM -  HERE 224 + UMAX  -2 AND  \ less room:
  DUP 200 + DICT-END @ U> IF -8 THROW THEN  DUP TEMP-START ! DP !  \ what there is
  'DOCOL JSR-IP CF,  DEPTH TEMP-DEPTH !  ] ;
: TEMP-FORGET  ( -- )  \ after an error in a run: the dictionary's end back
  TEMP-END @ IF HEAP @ TEMP-HEAP @ = IF TEMP-END @ DICT-END ! THEN 0 TEMP-END ! THEN ;
: TEMP-RUN  ( -- )  \ HERE back where it was, the dictionary ending below the code
  TEMP-HERE @ DP !  DICT-END @  TEMP-END @ 0=  ( end outermost? )
  DUP IF OVER TEMP-END !  HEAP @ TEMP-HEAP ! THEN  2>R
  TEMP-START @ DUP DICT-END !  (EXECUTE)
  2R> SWAP HEAP @ TEMP-HEAP @ = IF DICT-END ! ELSE DROP THEN  IF 0 TEMP-END ! THEN ;
: TEMP-END?  ( -- )  \ structure closed (by a word compiling): run it
  TEMP-DEPTH @ STATE @ AND IF DEPTH 1+ TEMP-DEPTH @ = IF
    ['] EXIT ,  POSTPONE [  0 TEMP-DEPTH !  TEMP-RUN
  THEN THEN ;
: INTERPRET  ( -- )
  BEGIN PARSE-NAME DUP WHILE
    2DUP WHAT 2!  2DUP SEARCH-NAME ?DUP IF
      NIP NIP DUP NAME> SWAP C@
      STATE @ IF 128 AND IF (EXECUTE) ELSE COMPILE, THEN
      ELSE 64 AND IF OPENER? 0= IF -14 THROW THEN TEMP-BEGIN THEN (EXECUTE) THEN
    ELSE NUMBER THEN
    ?STACK TEMP-END?
  REPEAT 2DROP ;
: EVALUATE  ( a u -- )  \ CORE, BLOCK
  SRC 2@ 2>R  >IN @ >R  BLK @ >R  SRC-ID @ >R
  SRC 2!  0 >IN !  0 BLK !  -1 SRC-ID !  INTERPRET
  R> SRC-ID !  R> BLK !  R> >IN !  2R> SRC 2! ;

\ ---- reverse lookup: which word holds an address -----------------------------------
\ A chain runs from the newest header down, so the headers above an address are
\ skipped with one comparison each; a chain whose newest header is below the
\ best found so far is not walked (WORD-AT, trap reports)
CODE BELOW-IN  ( a wid -- lfa | 0 )  \ wid's newest header at or below a, of all its chains
  W S )+ MOV,  R3 W MOV,  R3 CHAIN-BYTES # ADD,  T CLR,
  BEGIN,
    R0 W )+ MOV,
    T R0 CMP,  HI IF,
      BEGIN,  S ) R0 CMP,  HI WHILE,  R0 R0 ) MOV,  REPEAT,
      T R0 CMP,  HI IF,  T R0 MOV,  THEN,
    THEN,
    R3 W CMP,
  EQ UNTIL,
  S ) T MOV,  NEXT,  END-CODE
VARIABLE BEST  ( -- a )
: BEST-IN  ( addr wid -- addr )  \ its newest word whose code starts at or below
  >R DUP BEGIN R@ BELOW-IN ?DUP WHILE  ( addr lfa )   \ addr; keep the best
    DUP 2+ NAME> 2 PICK U> 0= IF  2+ BEST @ UMAX BEST !  R> DROP EXIT  THEN  2-
  REPEAT R> DROP ;
: WORD-AT  ( addr -- nfa | 0 )  \ the word whose code or body holds addr
  0 BEST !  DUP HERE U< IF VOC-LINK @ BEGIN ?DUP WHILE   \ nothing at or above HERE
    DUP LINK>WID ROT SWAP BEST-IN SWAP @
  REPEAT THEN DROP BEST @ ;
: >NAME  ( xt -- nfa | 0 )  DUP WORD-AT DUP IF TUCK NAME> <> IF DROP 0 THEN ELSE NIP THEN ;
\ EXECUTE runs only an execution token: a code field the kernel or a defining
\ word laid down. A colon, CREATE, VARIABLE, CONSTANT, DOES> or SYNONYM code
\ field is recognised by its JSR or JMP and where it leads (a few instructions);
\ anything else must be a CODE word's, which its header proves (>NAME: the
\ headers above it are skipped, one comparison each). Data (VARIABLE v  v
\ EXECUTE) or a number is error -258 instead of a run into it.
: XT-HEADER  ( xt -- xt )  DUP >NAME 0= IF -258 THROW THEN ;
CODE (RESUME)  ( xt -- ) ( R: ip -- )  IP RP )+ MOV,  R0 S )+ MOV,  R0 ) JMP,  END-CODE
CODE EXECUTE  ( xt -- )  \ CORE
  R0 S ) MOV,
  BEGIN,  \ through SYNONYMs (JMP @#xt) to the word itself
    ?ODD,  ORIGIN # R0 CMP,  LO IF,  -258 THROW,  THEN,
    ' DP >BODY @# R0 CMP,  HIS IF,  -258 THROW,  THEN,
    137O # R0 ) CMP,
  EQ WHILE,  R0 2 R0 I) MOV,  REPEAT,
  4437O # R0 ) CMP,  EQ IF,  \ JSR IP: a colon definition
    DOCOL # 2 R0 I) CMP,  EQ IF,  S 2 # ADD,  R0 ) JMP,  THEN,
    -258 THROW,
  THEN,
  4237O # R0 ) CMP,  EQ IF,  \ JSR W: CREATE, CONSTANT, or a DOES> child
    T 2 R0 I) MOV,  DOVAR # T CMP,  EQ IF,  S 2 # ADD,  R0 ) JMP,  THEN,
    DOCON # T CMP,  EQ IF,  S 2 # ADD,  R0 ) JMP,  THEN,
    T 1 # BIT,  EQ IF,  ORIGIN # T CMP,  HIS IF,  ' DP >BODY @# T CMP,  LO IF,
      4437O # T ) CMP,  EQ IF,  DODOES # 2 T I) CMP,  EQ IF,  S 2 # ADD,  R0 ) JMP,  THEN,  THEN,
    THEN,  THEN,  THEN,
    -258 THROW,
  THEN,
  S ) R0 MOV,  RP -) IP MOV,  IP HERE 6 + # MOV,  NEXT,  ' XT-HEADER ,  ' (RESUME) ,
  END-CODE
: .NAME  ( nfa -- )  COUNT 31 AND TYPE ;
: .OCTAL  ( u -- )  BASE @ >R 8 BASE ! 0 <# # # # # # # #> TYPE R> BASE ! ;

\ ---- error reports -------------------------------------------------------------
VARIABLE DISARMED  ( -- a ) \ vector DISARM put back, -1 = none
VARIABLE TRAP-SEEN  ( -- a ) \ vector of the trap being reported, -1 = none
VARIABLE TRAP-WORD  ( -- a ) \ the word holding its PC, 0 = none
: DISARM  ( -- )  \ THROW -256: take over what TRAPPED recorded, if anything;
  -1 DISARMED !  0 TRAP-WORD !  TRAP-VEC @ TRAP-SEEN !  -1 TRAP-VEC !
  TRAP-SEEN @ 0< IF EXIT THEN  \ an interrupt handler that trapped leaves its vector
  TRAP-PC @ WORD-AT DUP TRAP-WORD !  ?DUP 0= IF EXIT THEN
  1000O 100O DO  \ only vectors a program installed (! refuses 0-77): a lookup each
    I @ STUBS I + <> IF I @ WORD-AT OVER = IF STUBS I + I !  I DISARMED ! THEN THEN
  4 +LOOP DROP ;
\ A memory management abort on page 6 is an access beyond S0 (boot.fs sets
\ the page's length there): a word took more than the data stack held. It
\ becomes error -4, stack underflow, like gforth's; the access was aborted, so
\ nothing was written. Any other trap may have followed a wild run:
\ CHECK-BUFFERS (disk.fs) sets aside the UPDATEd buffers it could have damaged.
: TRAP-CODE  ( -256 -- code )
  TRAP-SEEN @ MMU-VECTOR = IF
    MMR0 @  1 MMR0 !  40176O AND 40014O = IF DROP -4  -1 TRAP-SEEN ! EXIT THEN
  THEN
  TRAP-SEEN @ 0< 0= IF CHECK-BUFFERS THEN ;
: .DISARMED  ( -- )
  DISARMED @ DUP 0< IF DROP EXIT THEN
  ." ; vector " .OCTAL ."  restored to its default handler"  -1 DISARMED ! ;
: .TRAP  ( -- )  \ what the last unexpected trap was, and where
  TRAP-SEEN @ DUP 4 = IF ." bus error or odd address" ELSE
    DUP 10O = IF ." illegal or reserved instruction" ELSE
    DUP 14O = IF ." breakpoint trap (BPT)" ELSE
    DUP 20O = IF ." IOT trap" ELSE
    DUP 30O = IF ." EMT trap" ELSE
    DUP 34O = IF ." TRAP instruction" ELSE
    DUP 24O = IF ." power fail" ELSE
    DUP MMU-VECTOR = IF ." memory management abort" ELSE
    ." unexpected interrupt" THEN THEN THEN THEN THEN THEN THEN THEN
  ."  (vector " .OCTAL ." , PC " TRAP-PC @ .OCTAL
  TRAP-WORD @ ?DUP IF ."  in " .NAME THEN  .DISARMED ." )" ;
\ The messages of the error codes: code, counted string, aligned; 0 ends it.
CREATE ERROR-TEXTS  ( -- a )
  -1 , ," aborted"
  -3 , ," stack overflow"
  -4 , ," stack underflow"
  -5 , ," return stack overflow"
  -6 , ," return stack underflow"
  -8 , ," dictionary full"
  -9 , ," invalid memory address"
  -10 , ," division by zero"
  -13 , ," undefined word"
  -14 , ," compile-only word interpreted"
  -15 , ," cannot forget kernel words"
  -16 , ," name expected"
  -17 , ," pictured numeric output too long"
  -18 , ," string longer than 256 characters"
  -19 , ," name longer than 31 characters"
  -21 , ," unsupported operation (a DEFER without an action?)"
  -22 , ," unbalanced control structure"
  -24 , ," BASE outside 2..36 (now DECIMAL)"
  -23 , ," odd address for a word access"
  -28 , ," interrupted by ^C"
  -33 , ," block read error"
  -34 , ," block write error"
  -35 , ," no such block"
  -49 , ," search-order overflow"
  -50 , ," search-order underflow"
  -257 , ," return stack unbalanced (EXIT into data)"
  -258 , ," not an execution token"
  -259 , ," protected address (the kernel's trap and console vectors)"
  0 ,
: .ERROR-TEXT  ( code -- )
  DUP -2 = IF DROP ABORT-MSG @ COUNT TYPE EXIT THEN
  DUP -256 = TRAP-SEEN @ 0< 0= AND IF DROP .TRAP EXIT THEN
  ERROR-TEXTS BEGIN DUP @ WHILE
    2DUP @ = IF NIP 2+ COUNT TYPE EXIT THEN  2+ COUNT + ALIGNED
  REPEAT DROP  ." error " 0 .R ;
\ An undefined word that a vocabulary outside the search order holds (the
\ editor's P before EDITOR was typed): say which vocabulary to type.
: IN-ORDER?  ( wid -- f )  \ is wid in the search order?
  FALSE #ORDER @ 2* CONTEXT + CONTEXT ?DO OVER I @ = OR 2 +LOOP NIP ;
: .ELSEWHERE  ( -- )
  VOC-LINK @ BEGIN ?DUP WHILE
    DUP LINK>WID  DUP VOC-NAME OVER IN-ORDER? 0= AND IF
      WHAT 2@ 2 PICK WID-FIND IF
        ."  (a word of " DUP VOC-NAME .NAME ." : type " VOC-NAME .NAME
        ."  to select it again)" DROP EXIT
      THEN
    THEN DROP @
  REPEAT ;
: .ERROR  ( code -- )  \ Error: what: word [in block b line l] [(where it is)]
  CR ." Error: " DUP .ERROR-TEXT  WHAT 2@ ?DUP IF ." : " TYPE ELSE DROP THEN
  ERR-BLK @ IF ."  in block " ERR-BLK @ . ." line " ERR-IN @ 1- 0 MAX 64 / . THEN
  -13 = IF .ELSEWHERE THEN CR ;
: UNLINK  ( lfa -- )  \ a definition cut short leaves, HERE goes back to it, and
  (FORGET) ;  \ so does what was defined after it ([ CREATE X ] inside it): no chain
              \ may keep a header above HERE, where the next one would overwrite it
: DISCARD-DEFINITION  ( -- )  \ a definition cut short leaves nothing behind
  STATE @ IF COLON-LFA @ ?DUP IF UNLINK THEN THEN
  0 COLON-LFA !  NO-LOOPS  TEMP-DEPTH @ IF TEMP-HERE @ UNLINK  0 TEMP-DEPTH ! THEN  TEMP-FORGET ;
: CLEAR-STACK  ( -- )  S0 SP! ;  \ empty (what is beyond S0 traps: MMU-TRAP)
\ FORTH-79 makes CONTEXT CURRENT after an error; here only when the assembler is
\ the context (a CODE word cut short), so an error while editing keeps EDITOR.
: CONTEXT-AFTER-ERROR  ( -- )  \ an empty order: the boot one
  #ORDER @ 0= IF ONLY ALSO THEN  CONTEXT @ ASSEMBLER-BODY = IF CURRENT @ VOC-CONTEXT THEN ;
: RESET-AFTER-ERROR  ( -- )
  DISCARD-DEFINITION  POSTPONE [  0 BLK !  0 SRC-ID !  CONTEXT-AFTER-ERROR
  'ON-ERROR @ ?DUP IF EXECUTE THEN  0 PRIORITY! ;

\ ---- QUIT --------------------------------------------------------------------------
: .LOST  ( -- )  \ say so when the console ring overflowed, or ^C emptied it
  RXLOST @ ?DUP IF CR U. ." characters lost: typed too far ahead" CR  0 RXLOST ! THEN
  RXDROP @ ?DUP IF U. ." typed-ahead characters dropped by ^C" CR  0 RXDROP ! THEN ;
\ AWAIT-LINE reads the DL11's RCSR, which a DL11 ignores: the cue at which a scripted
\ run stops to type the next line (pdp11-devices/simh/prompt_cue.c), at no cost between
CODE AWAIT-LINE  ( -- )  177560O @# TST,  NEXT,  END-CODE  \ prompts (no breakpoint)
: QUERY  ( -- )  \ CORE EXT: a line from the terminal becomes the source
  AWAIT-LINE  0 0 WHAT 2!  TIB TIB-SIZE 1- ACCEPT  TIB SWAP SRC 2!  0 >IN !  0 BLK !  0 SRC-ID !  SPACE .LOST ;
: INTERPRET-LINE  ( -- )  QUERY INTERPRET ;
: .PROMPT  ( -- )  \ gforth's: an open definition or structure says so
  STATE @ TEMP-DEPTH @ OR IF ."  compiled" ELSE ."  ok" THEN CR ;
\ The cell at RP0 holds RS-GUARD, a thread of one word: an EXIT with the return
\ stack empty (RP0 RP!) runs it instead of popping the I/O page. No push: the
\ guard cell stays intact.
CODE RS-EMPTY  ( -- )  RP RP0 # MOV,  S -) CLR,  -6 THROW,  END-CODE
CREATE RS-GUARD  ( -- a )  ' RS-EMPTY ,
: ABORT-TO-QUIT  ( code -- )  \ THROW with no CATCH frame, return stack emptied:
  >R CLEAR-STACK  BASE @ 2 37 WITHIN 0= IF DECIMAL THEN  \ a sane stack and BASE
  R> .ERROR  .LOST  RESET-AFTER-ERROR  QUIT ;            \ for the report
: QUIT  ( -- )  \ CORE: read, interpret: forever. An error is a THROW with no CATCH
  RS-GUARD RP0 !  RP0 RP!  0 HANDLER !  POSTPONE [  0 BLK !  0 PRIORITY!  \ frame:
  BEGIN 0 HANDLER ! INTERPRET-LINE .PROMPT AGAIN ;  \ it reports, resets, QUITs
  \ again; no CATCH frame outlives a line (a word that dropped CATCH's return)
