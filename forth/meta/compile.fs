\ forth/meta/compile.fs: host versions of the target's compiling words. They run
\ on the host while a target colon definition is compiled and lay down the same
\ threads the target's own IF, DO, ." ... lay down at run time.
\ Control-flow items carry a tag so that a mismatch is reported, not compiled:
\ 1 = orig (forward branch), 2 = dest (backward target), 3 = DO, 4 = colon.

: pair? ( tag expected -- )
  <> if s" unbalanced control structure" meta-error then ;
: >mark ( -- orig 1 )  there 0 t, 1 ;
: >resolve ( orig 1 -- )  1 pair? there swap t! ;
: <mark ( -- dest 2 )  there 2 ;
: <resolve ( dest 2 -- )  2 pair? t, ;
: t-string ( addr u -- )  \ counted string inline in the thread, padded to even
  dup tc, bounds ?do i c@ tc, loop talign ;

\ the primitive EXIT, captured after prims.fs (build.fs): locals.fs later defines an
\ IMMEDIATE EXIT for programs (it drops a locals frame first), which ; must not call
variable exit-cfa
: exit, ( -- )  exit-cfa @ dup 0= if drop [t] EXIT then t, ;

get-current  metac-wl set-current

: ( ( "text<paren>" -- )  [char] ) parse 2drop ;
: \ ( "line" -- )  source nip >in ! ;
: [ ( -- )  tstate off ;
: ; ( colon 4 -- )
  exit,  4 pair?  $20 tunflag  tstate off ;
: IF ( -- orig )  [t] ?BRANCH t, >mark ;
: ELSE ( orig -- orig' )  [t] BRANCH t, >mark 2swap >resolve ;
: THEN ( orig -- )  >resolve ;
: BEGIN ( -- dest )  <mark ;
: UNTIL ( dest -- )  [t] ?BRANCH t, <resolve ;
: END ( dest -- )  [t] ?BRANCH t, <resolve ;
: AGAIN ( dest -- )  [t] BRANCH t, <resolve ;
: WHILE ( dest -- orig dest )  [t] ?BRANCH t, >mark 2swap ;
: REPEAT ( orig dest -- )  [t] BRANCH t, <resolve >resolve ;
: DO ( -- do-sys )  [t] (DO) t, there 0 t, 3 ;
: ?DO ( -- do-sys )  [t] (?DO) t, there 0 t, 3 ;
: LOOP ( do-sys -- )  3 pair? [t] (LOOP) t, dup 2 + t, there swap t! ;
: +LOOP ( do-sys -- )  3 pair? [t] (+LOOP) t, dup 2 + t, there swap t! ;
: LITERAL ( n -- )  t-literal ;
: ['] ( "name" -- )  parse-name tcfa-of t-literal ;
: ' ( "name" -- )  parse-name tcfa-of t-literal ;  \ the target's ' is FORTH-79's
: [CHAR] ( "c" -- )  parse-name drop c@ t-literal ;
: ." ( "ccc"" -- )  [t] (.") t, [char] " parse t-string ;
: S" ( "ccc"" -- )  [t] (S") t, [char] " parse t-string ;
: ABORT" ( "ccc"" -- )  [t] (ABORT") t, [char] " parse t-string ;
: RECURSE ( -- )  tlast-m @ m-cfa t, ;
: [COMPILE] ( "name" -- )  parse-name tcfa-of t, ;
: POSTPONE ( "name" -- )
  parse-name 2dup tfind dup 0= if drop s" POSTPONE of an undefined word: " pad place
    pad +place pad count meta-error then
  nip nip dup m-immediate? if m-cfa t, else m-cfa t-literal [t] COMPILE, t, then ;
: DOES> ( -- )  \ child's code field will JSR W to here; here JSR IP to DODOES
  [t] (DOES>) t,  there tlast-m @ m-does !  jsr-ip s" DODOES" jsr-cf ;

set-current
