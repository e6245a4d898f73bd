\ tests/forth/tester.fs: the { ... -> ... } harness the Hayes core test
\ expects, written for this project. A failing test prints a line starting
\ with "TEST FAILED:" and counts; #TESTS and #FAILED tell the totals.
VARIABLE #TESTS  ( -- a )
VARIABLE #FAILED  ( -- a )
VARIABLE DEPTH0  ( -- a ) \ depth at {
VARIABLE #ACTUAL  ( -- a ) \ results between { and ->
CREATE ACTUAL 32 CELLS ALLOT  ( -- a )
: FAIL  ( a u -- )  CR ." TEST FAILED: " TYPE ." : " SOURCE TYPE  1 #FAILED +! ;
: {  ( -- )  1 #TESTS +!  DEPTH DEPTH0 ! ;
: ->  ( x* -- )  \ keep the results, leave the stack as it was at {
  DEPTH DEPTH0 @ - DUP #ACTUAL !
  DUP 0< IF DROP S" stack shrank below {" FAIL EXIT THEN
  0 ?DO ACTUAL I CELLS + ! LOOP ;
: }  ( x* -- )  \ the expected values against the kept ones
  DEPTH DEPTH0 @ - #ACTUAL @ <> IF
    S" wrong number of results" FAIL  DEPTH0 @ 0 MAX BEGIN DEPTH OVER > WHILE NIP REPEAT DROP
    EXIT THEN
  #ACTUAL @ 0 ?DO ACTUAL I CELLS + @ <> IF S" wrong result" FAIL THEN LOOP ;
: TESTING  ( "rest" -- )  SOURCE NIP >IN ! ;
