# mk/harness.mk: the harness's scripted runs and regression suite.
#   make regression          run tests/regression/scenarios against their goldens
#   make regression-update   rewrite the goldens and print what changed
#   make bench-harness       wall time of one scenario with boot (in process and
#                            from the command line), of the regression suite and
#                            of make test, the real-time factor, the idle console's
#                            share of a core (part of make bench)
#   make bench-timed         SET CLK TIMED against harness timing's price, and the
#                            FORTH's and the servo's figures in 11/23 time (part of make bench)
HARNESS_NEEDS := $(BUILD)/pdp11 $(BUILD)/pdp11-timed $(BUILD)/kernel.lda $(BUILD)/kernel.map $(PRISTINE_DSK) venv

regression: $(HARNESS_NEEDS)  ## the regression scenarios against their goldens
	@$(PY) -m harness regress

regression-update: $(HARNESS_NEEDS)  ## re-record the regression goldens
	@$(PY) -m harness regress --update

bench-harness: $(HARNESS_NEEDS)  ## the harness's figures: make test's time, real-time factor, idle console's CPU
	@$(PY) -m harness.bench.run_bench

BENCHES += bench-harness
.PHONY: regression regression-update bench-harness

# SET CLK TIMED (pdp11-devices/simh/kdf11_time.c) against harness timing's price, and
# the FORTH's and the servo's figures in both time bases (about 10 s)
bench-timed: $(HARNESS_NEEDS)  ## SET CLK TIMED against harness timing's price, servo moves in both time bases
	@$(PY) -m harness.bench.timed_bench
BENCHES += bench-timed
.PHONY: bench-timed
