# mk/asm.mk: what the assembler's encoding checks (tests/asm) need: gforth (the
# host assembler) and SIMH's stock PDP-11 simulator (its disassembler is one of
# the references). pdpy11, the other reference, is pinned in requirements.txt.
ALL_PRODUCTS += $(BUILD)/pdp11-stock asm-gforth

asm-gforth:  ## install gforth, the host assembler the encoding checks use
	@bash mk/apt-need.sh gforth

.PHONY: asm-gforth
