\ forth/meta/target.fs: which PDP-11 the kernel is built for.
\ The 11/23 by default (build.fs -> build/kernel.lda). build-1103.fs defines
\ LSI-11 true first (-> build/kernel-1103.lda): the LSI-11/03 has no memory
\ management, so ENTRY's MMU setup, between MMU{ and }MMU in boot.fs, becomes
\ dead code behind a BR. Nothing else moves: both images share one layout and
\ one map, and the 11/23's image stays byte for byte what it was.
[undefined] lsi-11 [if] false constant lsi-11 [then]
variable mmu-from  \ target address of the first instruction of the MMU setup
: MMU{ ( -- )  there mmu-from ! ;
: }MMU ( -- )  \ on the 11/03, overwrite that first instruction with BR here
  lsi-11 0= if exit then
  there mmu-from @ 2 + - 2/  dup 127 u> abort" the MMU setup is too long for a BR"
  $100 or  mmu-from @ t! ;
