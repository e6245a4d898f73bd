\ forth/meta/defs.fs: the metacompiler's own words, as kernel sources see them.
\ meta-wl: defining words and dictionary words acting on the TARGET image.
\ metac-wl: host versions of the target's compiling words, run while a target
\ colon definition is being compiled (they lay down target threads).

get-current  meta-wl set-current

: ( ( "text<paren>" -- )  [char] ) parse 2drop ;
: \ ( "line" -- )  source nip >in ! ;
: .( ( "text<paren>" -- )  [char] ) parse type ;
: OCTAL ( -- )  8 base ! ;
: INCLUDE ( "file" -- )  parse-name meta-include ;
: , ( x -- ) t, ;
: C, ( c -- ) tc, ;
: ," ( "text<quote>" -- )  \ a counted string, then aligned (tables of messages)
  [char] " parse  dup tc,  0 ?do  dup i + c@ tc,  loop drop  talign ;
: ALLOT ( n -- ) tallot ;
: ALIGN ( -- ) talign ;
: HERE ( -- ta ) there ;
: ' ( "name" -- cfa )  parse-name tcfa-of ;
: >BODY ( cfa -- pfa )  4 + ;
: IMMEDIATE ( -- )  $80 tflag ;
: COMPILE-ONLY ( -- )  $40 tflag ;
: ] ( -- )  tstate on ;
: LABEL ( "name" -- )  \ a host constant = target address; assemble after it
  close-code  parse-name 2dup there -rot map-add
  get-current >r label-wl set-current nextname there constant r> set-current
  start-code-body code-mode on ;
: EQU ( x "name" -- )  \ a host-side address or value, listed in the map
  parse-name 2dup 4 pick -rot map-add
  get-current >r label-wl set-current nextname constant r> set-current ;
: CODE ( "name" -- )  close-code  parse-name theader  start-code-body code-mode on ;
: END-CODE ( -- )  code-mode @ 0= abort" END-CODE outside CODE" close-code ;
: : ( "name" -- )
  close-code  parse-name theader  $20 tflag  jsr-ip s" DOCOL" jsr-cf
  4 tstate on ;
: CREATE ( "name" -- )  t-create ;
: VARIABLE ( "name" -- )  t-create 0 t, ;
: CONSTANT ( n "name" -- )  t-constant ;
: VALUE ( n "name" -- )  t-constant ;
: CON ( n "name" -- )  t-constant ;
: VAR ( n "name" -- )  t-create t, ;
: ARRAY ( n "name" -- )  t-create 2* tallot ;
: VOCABULARY ( "name" -- )
  \ target body: the heads of its #chains chains, its VOC-LINK cell, its NFA;
  \ its code is the DOES> part of the target's VOCABULARY
  close-code  parse-name
  2dup s" FORTH" ci= if tforth else tvoc-new then >r
  s" VOCABULARY" tfind dup 0= if s" VOCABULARY must be defined first" meta-error then
  m-does @ >r  2dup theader  jsr-w t, r> t,  $80 tflag
  there r@ voc-body !  #chains 0 do 0 t, loop  tvoc-link @ t,  there 2 - tvoc-link !  tlast-nfa @ t,
  2dup r@ -rot meta-wl voc-setter  r> -rot metac-wl voc-setter ;
: FORTH ( -- )  tforth tcontext ! ;
: DEFINITIONS ( -- )  tcontext @ tcurrent ! ;

set-current
