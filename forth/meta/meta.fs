\ forth/meta/meta.fs: the metacompiler proper. Host (gforth) and target are kept
\ apart: target words exist on the host only as MIRRORS (a host word per target
\ word, in a host wordlist per target vocabulary, holding the target code field
\ address and name field address); target code is never executed on the host.
\ Kernel sources are read by the metacompiler's own outer interpreter (not
\ gforth's), so every name is resolved deliberately:
\   compiling (inside a target : definition):
\     1. host versions of the target's compiling words (metac-wl: IF ; DOES> ...)
\     2. target vocabularies (the meta CONTEXT, then FORTH): compile the xt
\     3. an EQU or LABEL name, or a number (trailing O = octal): (LIT) n
\     4. otherwise a FORWARD REFERENCE, patched when the word is defined and
\        reported (file:line) if it never is.
\   interpreting: the assembler (inside CODE/LABEL), the metacompiler's words
\     (meta-wl: defining words, , ALLOT ...), labels, gforth; then a number.

wordlist constant meta-wl    \ interpret-state metacompiler words
wordlist constant metac-wl   \ host versions of compiling (immediate) target words
wordlist constant label-wl   \ LABELs: host constants holding target addresses

\ ---- error reporting with the source position ------------------------------
create src-name 256 allot  variable src-line
create line-buf 256 allot  variable line-len
: .where ( -- )  src-name count type ." :" src-line @ 0 .r ." : " ;
: meta-error ( addr u -- )  \ report and exit non-zero
  cr .where type cr ." >>> " line-buf line-len @ type cr  1 (bye) ;

\ ---- case-insensitive names --------------------------------------------------
: upc ( c -- C )  dup [char] a [char] z 1+ within if 32 - then ;
: ci= ( a1 u1 a2 u2 -- f )
  rot over <> if drop 2drop false exit then
  0 ?do over i + c@ upc over i + c@ upc <> if 2drop false unloop exit then loop
  2drop true ;
: $copy ( addr u -- host-counted )  here >r dup c, bounds ?do i c@ c, loop align r> ;

\ ---- the symbol map (build/kernel.map) ---------------------------------------
4000 constant max-map
create map-tab max-map 2* cells allot  variable #map  variable map-fd
: map-add ( ta addr u -- )  \ remember name and target address
  #map @ max-map = abort" map table full"
  $copy  #map @ 2* cells map-tab + tuck cell+ ! !  1 #map +! ;
: .oct6 ( n -- )  base @ >r 8 base ! 0 <# # # # # # # #> type r> base ! ;
: write-map ( c-addr u -- )  \ "oooooo name" per line, in definition order
  w/o create-file throw map-fd !  base @ >r 8 base !
  #map @ 0 ?do
    i 2* cells map-tab + dup @ 0 <# # # # # # # #> map-fd @ write-file throw
    s"  " map-fd @ write-file throw  cell+ @ count map-fd @ write-line throw
  loop r> base !  map-fd @ close-file throw ;

\ ---- target vocabularies on the host -----------------------------------------
\ host voc: +0 host wordlist  +1..+#chains the heads of its chains (target LFA
\ of the newest word of each chain: name-chain)  then the target body address
\ of the vocabulary word (0 until defined), the next host voc
32 constant #chains   \ a power of 2; also the kernel's (prims.fs CHAIN-OFFSET, interp.fs) and,
\ through build/kernel.map's #CHAINS, the harness's (kernel_layout.CHAINS). Issue 19: 32
\ chains cut the interpreter to ~1 130 instructions a word (8: 1 721); their 48 bytes a word
\ list come from the S" ring moved out of the dictionary (memory.fs SBUFS)
: name-chain ( addr u -- i )  \ as CHAIN-OFFSET: upper-cased first character
  2* swap c@ upc + #chains 1- and ;   \ plus twice the length, mod #chains
0 value tvocs
: tvoc-new ( -- voc )
  wordlist  here swap ,  #chains 0 do 0 , loop  0 , tvocs ,  dup to tvocs ;
: voc-wid ( voc -- wid ) @ ;
: voc-heads ( voc -- a ) cell+ ;
: voc-body ( voc -- a ) #chains 1+ cells + ;
: voc-next ( voc -- a ) #chains 2 + cells + ;
tvoc-new constant tforth
variable tcurrent  tforth tcurrent !
variable tcontext  tforth tcontext !

\ mirror (body of a host word): +0 target cfa  +1 target nfa  +2 DOES> code addr
: m-cfa ( m -- ta ) @ ;
: m-nfa ( m -- ta ) cell+ @ ;
: m-does ( m -- a ) 2 cells + ;
: m-immediate? ( m -- f ) m-nfa tc@ $80 and 0<> ;
: voc-find ( addr u voc -- m|0 )  voc-wid search-wordlist if >body else 0 then ;
: tfind ( addr u -- m|0 )  \ meta CONTEXT, then FORTH
  2dup tcontext @ voc-find ?dup if nip nip exit then  tforth voc-find ;
: tcfa-of ( addr u -- ta )
  2dup tfind ?dup if nip nip m-cfa exit then
  s" target word not defined yet: " pad place pad +place pad count meta-error ;
: [t] ( "name" -- )  \ compile into a host definition: target cfa of name
  parse-name postpone sliteral postpone tcfa-of ; immediate

\ ---- forward references -------------------------------------------------------
\ record: +0 host counted name  +1 target address to patch  +2 counted where
1000 constant max-fwd
create fwd-tab max-fwd 3 * cells allot  variable #fwd  variable fwd-cfa
: fwd ( n -- a ) 3 * cells fwd-tab + ;
: where$ ( -- host-counted )
  src-name count pad place s" :" pad +place src-line @ 0 <# #s #> pad +place
  pad count $copy ;
: fwd-add ( addr u -- )  \ compile a placeholder for a word not yet defined
  #fwd @ max-fwd = abort" forward reference table full"
  $copy #fwd @ fwd !  there #fwd @ fwd cell+ !  where$ #fwd @ fwd 2 cells + !
  1 #fwd +!  0 t, ;
: fwd-resolve ( addr u cfa -- )  \ patch every pending reference to name
  fwd-cfa !  #fwd @ 0 ?do
    i fwd @ ?dup if count 2over ci= if fwd-cfa @ i fwd cell+ @ t!  0 i fwd ! then then
  loop 2drop ;
: fwd-report ( -- n )  \ unresolved references, listed; their number
  0 #fwd @ 0 ?do i fwd @ ?dup if
    i fwd 2 cells + @ count type ." : undefined target word " count type cr 1+
  then loop ;

\ ---- target headers --------------------------------------------------------------
\ LFA: link to the previous LFA of the same vocabulary (0 ends the chain)
\ NFA: count byte (bit 7 IMMEDIATE, bit 6 COMPILE-ONLY, bit 5 SMUDGE, 4-0 length),
\      the name as written, padded to an even address
\ CFA: machine code (CODE words) or JSR R,@#handler (all other words)
variable tlast-nfa  variable tlast-m
: theader ( addr u -- )
  dup 0= if s" name expected" meta-error then
  dup 31 u> if s" name longer than 31 characters" meta-error then
  2dup name-chain cells tcurrent @ voc-heads + >r  \ the name's chain
  talign  there  r@ @ t,  r> !
  there tlast-nfa !  dup tc,  2dup bounds ?do i c@ tc, loop  talign
  2dup there -rot map-add
  get-current >r  tcurrent @ voc-wid set-current
  2dup nextname create  r> set-current
  here tlast-m !  there , tlast-nfa @ , 0 ,
  there fwd-resolve ;
: tflag ( bits -- )  tlast-nfa @ tc@ or tlast-nfa @ tc! ;
: tunflag ( bits -- )  invert tlast-nfa @ tc@ and tlast-nfa @ tc! ;

\ code field handlers (LABELs defined in the kernel source)
: label-value ( addr u -- ta )
  2dup label-wl search-wordlist 0= if
    s" label not defined yet: " pad place pad +place pad count meta-error then
  nip nip execute ;
$091F constant jsr-ip   \ JSR R4,@#a  (colon definitions, DOES> code)
$089F constant jsr-w    \ JSR R2,@#a  (CREATE, VARIABLE, CONSTANT, children)
: jsr-cf ( opcode addr u -- )  label-value swap t, t, ;

\ ---- the metacompiler's outer interpreter ----------------------------------------
variable tstate      \ true while compiling a target definition
variable code-mode   \ true inside CODE / LABEL: the assembler is searched first

: tnumber? ( addr u -- n true | false )  \ optional -, trailing O/o = octal
  dup 0= if 2drop false exit then
  base @ >r
  2dup + 1- c@ upc [char] O = if 1- 8 base ! then
  over c@ [char] - = dup >r if 1 /string then
  dup 0= if r> r> base ! 2drop drop false exit then
  0 0 2swap >number nip nip r> swap r> base ! if 2drop false exit then
  if negate then true ;

: t-literal ( n -- )  [t] (LIT) t, t, ;
: t-compile ( addr u -- )
  2dup metac-wl search-wordlist if nip nip execute exit then
  2dup tfind ?dup if
    dup m-immediate? if drop s" target IMMEDIATE word has no metacompiler version: "
      pad place pad +place pad count meta-error then
    nip nip m-cfa t, exit then
  2dup label-wl search-wordlist if nip nip execute t-literal exit then
  2dup tnumber? if nip nip t-literal exit then
  fwd-add ;
: interp-find ( addr u -- xt true | false )
  code-mode @ if 2dup assembler-wordlist search-wordlist if nip nip true exit then then
  2dup meta-wl search-wordlist if nip nip true exit then
  2dup label-wl search-wordlist if nip nip true exit then
  forth-wordlist search-wordlist 0<> ;
: t-interpret ( addr u -- )
  2dup interp-find if nip nip execute exit then
  2dup tnumber? if nip nip exit then
  s" undefined in the metacompiler: " pad place pad +place pad count meta-error ;
: meta-line ( -- )  \ interpret the current input line
  begin parse-name dup while
    tstate @ if t-compile else t-interpret then
  repeat 2drop ;
: meta-include ( addr u -- )  \ read a kernel source file with this interpreter
  src-name count $copy >r src-line @ >r
  2dup src-name place  r/o open-file if s" cannot open" meta-error then >r
  0 src-line !
  begin line-buf 255 r@ read-line throw while
    line-len !  1 src-line +!
    line-buf line-len @ ['] meta-line ['] execute-parsing catch ?dup if
      cr .where ." error" cr ." >>> " line-buf line-len @ type cr
      ['] DoError catch drop cr 1 (bye) then
  repeat drop r> close-file throw
  r> src-line ! r> count src-name place ;

\ ---- helpers of the defining words (defs.fs) ----------------------------------------
: close-code ( -- )  \ a CODE or LABEL body ends: the assembler checks it
  code-mode @ if end-code-body  code-mode off then ;
variable tvoc-link  \ target address of the newest vocabulary's VOC-LINK cell
: voc-setter ( voc addr u wid -- )  \ host word: make voc the meta CONTEXT
  get-current >r set-current nextname create , r> set-current
  does> @ tcontext ! ;

\ meta words calling each other go through these (meta-wl is never in gforth's
\ search order, so a meta word cannot name another one)
: t-create ( "name" -- )  close-code  parse-name theader  jsr-w s" DOVAR" jsr-cf ;
: t-constant ( n "name" -- )  close-code parse-name theader jsr-w s" DOCON" jsr-cf t, ;
