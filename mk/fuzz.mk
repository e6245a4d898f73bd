# mk/fuzz.mk: the long checks of bad and large input (harness/fuzz/).
#   make fuzz                 the console fuzz of issue 8 (console_fuzz.py): 10 000
#                             seeded random lines, then a robot move, then 20
#                             rounds of a second simulator on the same image
#                             (two_writers.py); prints halts, hangs, reboots and
#                             failed rounds (all must be 0); then issue 23's:
#                             pastes of 5 000 and 30 000 characters into the
#                             console (both paces) and the lab page (paste_runs.py),
#                             and 50 000 malformed lab messages (protocol_fuzz.py)
#   make fuzz FUZZ_SEED=7 FUZZ_LINES=20000 FUZZ_MESSAGES=100000
#   make bench-paste          a 20 000-character paste's wall time at both paces
#                             (part of make bench)
# make test runs short versions: 2 000 lines (tests/forth/test_fuzz.py), a
# 1 000-character paste (tests/run/test_console_paste.py), 2 000 messages
# (tests/lab/test_lab_keys.py).
FUZZ_LINES ?= 10000
FUZZ_SEED  ?= 1983
FUZZ_MESSAGES ?= 50000
PASTE_NEEDS := $(BUILD)/pdp11 $(BUILD)/kernel.lda $(BUILD)/kernel.map $(BUILD)/robot.dsk \
               lab-assets venv

fuzz: $(PASTE_NEEDS)  ## the long input checks: FUZZ_LINES random console lines, two writers, pastes, lab messages
	@$(PY) -m harness.fuzz.console_fuzz --lines $(FUZZ_LINES) --seed $(FUZZ_SEED)
	@$(PY) -m harness.fuzz.paste_runs fuzz
	@$(PY) -m harness.fuzz.protocol_fuzz --messages $(FUZZ_MESSAGES) --seed $(FUZZ_SEED)

bench-paste: $(PASTE_NEEDS)  ## a 20 000-character paste's wall time at both paces
	@$(PY) -m harness.fuzz.paste_runs bench
BENCHES += bench-paste

.PHONY: fuzz bench-paste
