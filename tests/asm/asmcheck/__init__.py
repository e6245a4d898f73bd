"""Independent checks of the PDP-11 assembler's encoding (forth/asm.fs).

One corpus of pairs (FORTH destination-first text | MACRO-11 text, see
corpus.py) is assembled three ways and compared word for word:
pdpy11 on the MACRO-11 side, the host assembler under gforth on the FORTH side,
and SIMH's disassembler reading the host assembler's words back."""
