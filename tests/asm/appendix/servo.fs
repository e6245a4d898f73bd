\ tests/asm/appendix/servo.fs: the appendix's blocks 1000-1008 as the assembler
\ reads them, OCR repaired only where the assembler syntax needs it: `.` for
\ `,`, RP)+ spaced as RP )+, Desire. Pos joined, Cyrillic T, I for 1, the octal
\ mark as a trailing O, FORTH: as FORTH ; and END-CODE where block 1008 ends a
\ CODE word with the next definition. Layout and comments shortened.
\ The MACRO-11 translation beside it is servo.mac.
4 ARRAY Desire.Pos   4 ARRAY State   4 ARRAY MaxVel   4 ARRAY Velocity
4 ARRAY Increment    4 ARRAY 0-Vel   4 ARRAY Command.Status
4 ARRAY Delay.Left
170440O CON VelOut   167770O CON CntOut   167774O CON CntIn
5 VAR Range   30 VAR Delay   0 CON Stop   1 CON Move   0 VAR Dir

: Save-Regs ( <>--<>, Save used registers on return stack )
    ASSEMBLER RP -) R0 MOV,  RP -) T MOV,  RP -) W MOV,  FORTH ;
: Restore-Regs ( <>--<>, Restore registers from return stack )
    ASSEMBLER W RP )+ MOV,  T RP )+ MOV,  R0 RP )+ MOV,  FORTH ;

: Stop? ( <>-<>, Test for stop point )
    ASSEMBLER
                              R0 CLR,
    BEGIN,
                            T R0 MOV,
                               T ASL,
               W Desire.Pos T I) MOV,
                    CntOut @# R0 MOV,
                     W CntIn @# SUB,
          MI IF,               W NEG,
          THEN,
                     Range @# W CMP,
    LT IF,
          VelOut T I) 0-Vel T I) MOV,
               State T I) Stop # MOV,
                    Velocity T I) CLR,
              Command.Status T I) CLR,
    ELSE,
               State T I) Move # MOV,
    THEN,
                              R0 INC,
                          4 # R0 CMP,
    GE END,
    FORTH ;

: Change.Speed? ( <>--<>, Test for speed change & do it )
  ASSEMBLER
                              R0 CLR,
    BEGIN,
                            T R0 MOV,
                               T ASL,
               State T I) Stop # CMP,
      NE IF,
               W Desire.Pos T I) MOV,
                    CntOut @# R0 MOV,
                     W CntIn @# SUB,
        MI IF,
                               W NEG,
                    Dir @# -1 # MOV,
        ELSE,
                     Dir @# 1 # MOV,
        THEN,
             Command.Status T I) TST,
        EQ IF,
                 Delay.Left T I) DEC,
          EQ IF,
          Delay.Left T I) Delay @# MOV,
               0-Vel T I) Dir @# ADD,
          THEN,
        THEN,
                 Velocity T I) W CMP,
        LT IF,
                 Velocity T I) W MOV,
                           Dir @# TST,
          MI IF,               W NEG,
          THEN,
                    W 0-Vel T I) ADD,
                  VelOut T I) W MOV,
        ELSE,
        MaxVel T I) Velocity T I) CMP,
          LT IF,
      Velocity T I) Increment T I) ADD,
         Velocity T I) MaxVel T I) MOV,
          THEN,
                 W Velocity T I) MOV,
                           Dir @# TST,
          MI IF,               W NEG,
          THEN,
                    W 0-Vel T I) ADD,
                  VelOut T I) W MOV,
        THEN,
      THEN,
                              R0 INC,
                          4 # R0 CMP,
    GE END,
  FORTH ;

CODE Interrupt.Servo ( <>--<>, Interrupt servo routine )
    Save-Regs Stop? Change.Speed? Restore-Regs RTI,
END-CODE
0 VAR Proc.Status
CODE Restore.Processor ( <>--<>, Restore old processor status )
                 Proc.Status @# MTPS,
                                NEXT,
END-CODE
CODE Disable.Interrupts ( <>--<>, Disable all Interrupts )
                 Proc.Status @# MFPS,
                         340O # MTPS,
                                NEXT,
END-CODE
