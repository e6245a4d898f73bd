\ forth/meta/build.fs: metacompile the kernel; write build/kernel.lda and
\ build/kernel.map. Run from the repository root:
\   gforth forth/meta/build.fs -e bye
\ (forth/meta/build-1103.fs: the same kernel for the LSI-11/03, target.fs)
\ Exits non-zero, naming file and line, on any error or unresolved reference.

require load.fs

: kernel ( addr u -- )  meta-include ;

decimal
$400 tdp !    \ ORIGIN 002000: vectors and stubs below, filled at the end
s" forth/kernel/memory.fs" kernel
s" forth/kernel/prims.fs" kernel
s" EXIT" tcfa-of exit-cfa !   \ the primitive, for ; (compile.fs)
s" forth/kernel/core.fs" kernel
s" forth/kernel/interp.fs" kernel
s" forth/kernel/quit.fs" kernel
s" forth/kernel/tools.fs" kernel
s" forth/kernel/search.fs" kernel
s" forth/kernel/coreext.fs" kernel
s" forth/kernel/double.fs" kernel
s" forth/kernel/string.fs" kernel
s" forth/kernel/toolsext.fs" kernel
s" forth/kernel/facility.fs" kernel
s" forth/kernel/heap.fs" kernel
s" forth/kernel/disk.fs" kernel
s" forth/kernel/editor.fs" kernel
s" forth/asm-target.fs" kernel   \ vocabulary ASSEMBLER (the ASSEMBLER helper's binding)
s" forth/kernel/code.fs" kernel
s" forth/kernel/boot.fs" kernel
s" forth/kernel/locals.fs" kernel   \ last: its IMMEDIATE EXIT shadows the primitive

\ ---- finish: resolve, initialise the kernel's variables, vectors ---------------
: fail ( addr u -- )  cr type cr 1 (bye) ;
close-code
tstate @ [if] s" unfinished definition at the end of the kernel" fail [then]
fwd-report [if] s" unresolved forward references" fail [then]
: lbl ( "name" -- x )  parse-name label-value ;
: [lbl] ( "name" -- )  parse-name postpone sliteral postpone label-value ; immediate
: body! ( x "name" -- )  parse-name tcfa-of 4 + t! ;
there body! DP
there body! FENCE
tlast-nfa @ body! LAST
tvoc-link @ body! VOC-LINK
\ each vocabulary's chain heads into its target body
: write-heads ( -- )  tvocs begin ?dup while
    dup voc-body @ 0= if s" a vocabulary was never defined" fail then
    #chains 0 do  dup voc-heads i cells + @  over voc-body @ i 2* + t!  loop
    voc-next @ repeat ;
write-heads
\ vector v -> STUBS+v at priority 7; stub: JSR R0,@#TRAPPED, except the
\ console receiver (JMP @#RXINT) and the line clock (JMP @#TICK: counts ticks)
: fill-vectors ( -- )
  $200 0 do
    [lbl] STUBS i + i t!  $E0 i 2 + t!
    i $30 = if $5F [lbl] STUBS i + t!  [lbl] RXINT [lbl] STUBS i + 2 + t! else
    i $40 = if $5F [lbl] STUBS i + t!  [lbl] TICK [lbl] STUBS i + 2 + t! else
      $081F [lbl] STUBS i + t!  [lbl] TRAPPED [lbl] STUBS i + 2 + t! then then
  4 +loop
  \ 000040, a reserved instruction, fills the free dictionary space (boot.fs);
  \ vector 40 (no device uses it) holds another, 000010, so free space both
  \ jumped into and run as a thread (an xt of 40) traps
  $8 $20 t! ;
fill-vectors
\ the 11/03's banner names its machine (same length: the layout does not move)
: name-1103 ( -- )  s" BANNER" tcfa-of  there swap ?do
    i taddr 9 s" PDP-11/23" compare 0= if [char] 0 i 7 + tc! unloop exit then
  loop  s" BANNER's machine name not found" fail ;
lsi-11 [if] name-1103 [then]
: out-lda ( -- a u )  lsi-11 if s" build/kernel-1103.lda" else s" build/kernel.lda" then ;
: out-map ( -- a u )  lsi-11 if s" build/kernel-1103.map" else s" build/kernel.map" then ;
0 there lbl ENTRY out-lda write-lda
out-map write-map
.( kernel: ) there lbl ORIGIN - . .( bytes, ) 
lbl LIMIT there - 160 - . .( bytes free, entry ) lbl ENTRY .oct6 cr
