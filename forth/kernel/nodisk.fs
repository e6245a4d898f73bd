\ forth/kernel/nodisk.fs: used only while forth/kernel/disk.fs does not exist.
: BLOCK  ( n -- a )  DROP -35 THROW ;  \ BLOCK
: (BLOCK)  ( n -- a )  BLOCK ;
: CHECK-BUFFERS  ( -- )  ;  \ after a trap: no buffers to check
