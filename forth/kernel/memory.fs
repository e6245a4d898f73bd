\ forth/kernel/memory.fs: the memory map (octal addresses; see forth/README.md).
\ EQU names a host-side address for CODE words and lists it in build/kernel.map.
       0O EQU VECTORS     \ 000000-000777 trap and interrupt vectors
    1000O EQU STUBS       \ 001000-001777 default handler of vector v at STUBS+v
    2000O EQU ORIGIN      \ kernel code and dictionary from here up
  144000O EQU LIMIT       \ the dictionary ends below here
  144000O EQU BUFFERS     \ 144000-154377 block buffers (forth/kernel/disk.fs)
   10400O EQU BUFFERS-SIZE
  154400O EQU SYSCELLS    \ 154400-154777 cells the CODE words share
  154400O EQU RXHEAD      \   console ring: next slot the interrupt fills
  154402O EQU RXTAIL      \   console ring: next slot KEY takes
  154404O EQU RXLOST      \   characters dropped because the ring was full
  154406O EQU TRAP-VEC    \   vector of the last unexpected trap
  154410O EQU TRAP-PC     \   PC it interrupted
  154412O EQU THROW-CELL  \   THROW's code address: CODE words raise errors through it
  155000O EQU RING        \ 155000-155377 console receive ring (256 characters)
     377O EQU RING-MASK
  155400O EQU TIB0        \ 155400-155777 terminal input buffer
     128  EQU TIB-SIZE
  156000O EQU S-LIMIT     \ 156000-156757 data stack (grows down from S0)
  156760O EQU S0          \ 156760-156777 slack below the return stack
  157000O EQU R-LIMIT     \ 157000-157777 return stack = hardware stack
  160000O EQU RP0
