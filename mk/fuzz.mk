# mk/fuzz.mk: the console fuzz of issue 8 (harness/fuzz/console_fuzz.py).
#   make fuzz                 10 000 seeded random lines, then a robot move;
#                             prints halts, hangs and reboots (all must be 0)
#   make fuzz FUZZ_SEED=7 FUZZ_LINES=20000
# tests/forth/test_fuzz.py runs a short version (2 000 lines) in make test.
FUZZ_LINES ?= 10000
FUZZ_SEED  ?= 1983

fuzz: $(BUILD)/pdp11 $(BUILD)/kernel.lda $(BUILD)/kernel.map $(BUILD)/robot.dsk venv
	@$(PY) -m harness.fuzz.console_fuzz --lines $(FUZZ_LINES) --seed $(FUZZ_SEED)

.PHONY: fuzz
