\ forth/kernel/boot.fs: the entry point and the banner.

: BANNER  ( -- )
  CR ." PDP-11/23 FORTH (metacompiled on gforth) for the UMass LPR Cartesian robot"
  CR UNUSED U. ." bytes free.  Disk: RL02 on the RLV12 at 174400, blocks 0-10239."
  CR ;
: COLD  ( -- )
  FORTH-BODY CURRENT !  ONLY ALSO  DECIMAL  0 HANDLER !  0 BLK !  0 STATE !
  -1 TRAP-VEC !  CLEAR-STACK
  ['] CODE-ERROR 'ON-ERROR !
  BANNER ."  ok" CR  QUIT ;

\ unexpected traps and interrupts: vector v holds STUBS+v, whose stub is
\ JSR R0,@#TRAPPED; the vector is recovered from R0, the trap frame dropped,
\ and the interpreter's error path entered with -256 THROW, still at priority 7:
\ THROW first takes a handler that trapped out of its vector (DISARM), then
\ lowers the priority. The return stack restarts at the innermost CATCH frame
\ (THROW goes there anyway): the report does not depend on a sane RP.
LABEL TRAPPED
  R0 STUBS 4 + # SUB,  TRAP-VEC @# R0 MOV,
  RP )+ TST,  TRAP-PC @# RP )+ MOV,
  RP ' HANDLER >BODY @# MOV,  EQ IF,  RP RP0 # MOV,  THEN,
  \ S is kept when it lies in the data stack, so that THROW's pushes do not land
  \ on the cells a CATCH frame gives back (7 8 ' PEEK CATCH leaves 7 8 whole);
  \ beyond S0 (underflow), below S-LIMIT or odd, it restarts at S0
  S 1 # BIC,  R0 S MOV,  R0 S-LIMIT # SUB,  S0 S-LIMIT - # R0 CMP,
  HI IF,  S S0 # MOV,  THEN,  S -) -256 # MOV,  \ priority stays 7 until the report is out
  IP HERE 6 + # MOV,  NEXT,  ' THROW ,  END-CODE
LABEL TICK  ( line clock, vector 100, until a servo is installed: count ticks )
  TICKS 2 + @# 1 # ADD,  TICKS @# ADC,  RTI,  END-CODE

\ Machine entry (the start address in build/kernel.lda): stacks, console
\ receive interrupt on, free space filled, priority 0, then the thread holding COLD.
LABEL ENTRY
  340O # MTPS,  RP RP0 # MOV,  S S0 # MOV,
  RXHEAD @# CLR,  RXTAIL @# CLR,  RXLOST @# CLR,  XOFF-HELD @# CLR,  RXDROP @# CLR,  TICKS @# CLR,  TICKS 2 + @# CLR,  THROW-CELL @# ' THROW # MOV,
  177560O @# 100O # MOV,
  \ memory management on, in kernel mode, every page mapped to itself (18-bit
  \ mode): it costs no instruction; its one job is page 6's length, which ends
  \ at S0, so a word that takes more than the data stack holds traps (MMU-TRAP);
  \ the 11/03 has none and branches over it (forth/meta/target.fs)
  MMU{  R0 KIPDR # MOV,  T KIPAR # MOV,  W CLR,
  BEGIN,  R0 )+ 77406O # MOV,  T )+ W MOV,  W 200O # ADD,  T KIPAR 16 + # CMP,  EQ UNTIL,
  KIPDR 12 + @# S0 140000O - 100O / 1- 10O LSHIFT 6 + # MOV,   \ page 6 ends at S0
  KIPAR 14 + @# 7600O # MOV,   \ page 7: the I/O page
  MMR0 @# 1 # MOV,  }MMU
  \ free dictionary space holds a reserved instruction (000040): a wild jump past
  \ HERE traps and is reported instead of running into HALT (zero) and stopping;
  \ run as a thread it is the xt 40, and address 40 holds another (build.fs)
  R0 ' DP >BODY @# MOV,  BEGIN,  R0 )+ 40O # MOV,  LIMIT # R0 CMP,  HIS UNTIL,
  0 # MTPS,
  IP HERE 6 + # MOV,  NEXT,  ' COLD ,  END-CODE

\ The simulator's QUIT, EXIT and BYE at sim> start the machine here when blocks
\ are UPDATEd (pdp11-devices/leave_check.c), whatever it was doing: fresh stacks,
\ then the thread ['] FLUSH CATCH DROP (BYE): a failed write is reported by the
\ driver and its block stays UPDATEd (the simulator reads BUF-UPD afterwards);
\ (BYE)'s HALT is where the simulator sees it done. Headerless, so that no
\ dictionary chain grows (FIND's timing, and the recorded runs, stay as they were).
LABEL LEAVE-ENTRY
  340O # MTPS,  RP RP0 # MOV,  S S0 # MOV,  0 # MTPS,
  IP HERE 6 + # MOV,  NEXT,  ' (LIT) ,  ' FLUSH ,  ' CATCH ,  ' DROP ,  ' (BYE) ,
  END-CODE
