\ forth/meta/build-1103.fs: metacompile the kernel for the LSI-11/03 (one per
\ axis, issue 21, docs/controllers.md); write build/kernel-1103.lda and .map.
\   gforth forth/meta/build-1103.fs -e bye
\ The 11/23's kernel with ENTRY's memory-management setup branched over
\ (target.fs) and "PDP-11/03" in the banner; same layout, same map.
true constant lsi-11
include build.fs
