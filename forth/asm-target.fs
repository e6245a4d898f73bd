( forth/asm-target.fs: the resident vocabulary ASSEMBLER.  The kernel   )
( build reads this file once VOCABULARY ASSEMBLER exists: it binds the  )
( assembler's four hooks to the dictionary and metacompiles asm.fs.     )
ASSEMBLER DEFINITIONS
: A, ( x -- ) , ;
: AHERE ( -- addr ) HERE ;
: A@ ( addr -- x ) @ ;
: A! ( x addr -- ) ! ;
INCLUDE forth/asm.fs
FORTH DEFINITIONS
