\ tests/asm/appendix/prelude.fs: just enough of the 1983 FORTH, on the host, to
\ run the appendix's CODE words through the host assembler: CON VAR ARRAY give
\ target addresses from 002000 up, ASSEMBLER and FORTH are immediate (FORTH-79),
\ CODE and END-CODE bracket a body.
variable target-data  1024 target-data !          \ 002000
: CON ( n "name" -- ) constant ;
: VAR ( n "name" -- ) drop target-data @ constant 2 target-data +! ;
: ARRAY ( n "name" -- ) target-data @ constant 2* target-data +! ;
: ASSEMBLER ( -- ) >asm ; immediate
: FORTH ( -- ) asm> ; immediate
: CODE ( "name" -- ) parse-name 2drop start-code-body ;
: END-CODE ( -- ) end-code-body ;
