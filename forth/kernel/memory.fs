\ forth/kernel/memory.fs: the memory map (octal addresses; see forth/README.md).
\ EQU names a host-side address for CODE words and lists it in build/kernel.map.
       0O EQU VECTORS     \ 000000-000777 trap and interrupt vectors
    1000O EQU STUBS       \ 001000-001777 default handler of vector v at STUBS+v
    2000O EQU ORIGIN      \ kernel code and dictionary from here up
  144000O EQU LIMIT       \ the dictionary ends below here
  144000O EQU BUFFERS     \ 144000-153777 reserved for block buffers (4 x 1024)
   10000O EQU BUFFERS-SIZE
  154000O EQU SYSCELLS    \ 154000-154377 cells the CODE words share
  154000O EQU RXHEAD      \   console ring: next slot the interrupt fills
  154002O EQU RXTAIL      \   console ring: next slot KEY takes
  154004O EQU RXLOST      \   characters dropped because the ring was full
  154006O EQU TRAP-VEC    \   vector of the last unexpected trap
  154010O EQU TRAP-PC     \   PC it interrupted
  154012O EQU THROW-CELL  \   THROW's code address: CODE words raise errors through it
  154014O EQU TICKS       \   60 Hz ticks the kernel's clock handler counted (double)
  154020O EQU XOFF-HELD   \   nonzero: XOFF sent to the terminal, XON not yet
  154022O EQU RXDROP      \   typed-ahead characters ^C dropped from the ring
  154024O EQU LOCALS-AREA \ 154024-154377 the names of a definition's locals (locals.fs),
      236 EQU LOCALS-SIZE \   out of the dictionary, which pays for its 32 hash chains
  154400O EQU RING        \ 154400-155377 console receive ring (511 characters)
     777O EQU RING-MASK
     384  EQU XOFF-MARK   \ characters in the ring that make RXINT send XOFF
  155400O EQU TIB0        \ 155400-155777 terminal input buffer
     256  EQU TIB-SIZE
  156000O EQU R-LIMIT     \ 156000-156675 return stack = hardware stack
  156676O EQU RP0         \ empty; the cell here holds RS-GUARD (an EXIT too many)
                          \ 156700-156777 a gap: what the interpreter pushes above
                          \   a full data stack lands there, not on the return stack
  157000O EQU S-LIMIT     \ 157000-157677 data stack (grows down from S0)
  157700O EQU S0          \ 157700-157777 beyond the MMU's page length: a word that
                          \   reads or writes below the empty data stack traps
\ KDF11-A memory management, kernel mode, pages mapped one to one (boot.fs)
  172300O EQU KIPDR       \ kernel page descriptor registers 0-7
  172340O EQU KIPAR       \ kernel page address registers 0-7
  177572O EQU MMR0        \ bit 0 enable; 14 page length error; 3:1 page
     250O EQU MMU-VECTOR  \ memory management abort
