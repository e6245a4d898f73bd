\ forth/meta/load.fs: the metacompiler, loaded into gforth (build.fs and the
\ tests include this, then read kernel sources with meta-include).
warnings off   \ gforth has its own A, and A!: ours are meant
require image.fs
require target.fs
include ../asm-host.fs
require meta.fs
require defs.fs
require compile.fs
require kmacros.fs
