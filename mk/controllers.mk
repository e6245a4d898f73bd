# mk/controllers.mk: the five machines of issue 21 (the 11/23 and four LSI-11/03s in
# lock-step on one plant, docs/controllers.md). The coordinator and the devices are
# built by mk/devices.mk; `make run CONTROLLERS=4` is in mk/run.mk.
#   make bench-controllers      aggregate rate of the five at full speed, the
#                               lock-step's overhead, one boundary's cost (part of make bench)
#   make controllers-runs       docs/servo.md's moves on the 11/23 alone and on the five,
#                               in build/controllers-runs/, and docs/img/controllers-*.png
#   make test-controllers-long  the long five-machine runs (not in make test, which has
#                               one end-to-end move and a kill at the launcher)
CONTROLLERS_NEEDS := $(BUILD)/pdp11 $(BUILD)/lockstep-coordinator $(BUILD)/kernel.lda \
                     $(BUILD)/kernel-1103.lda $(PRISTINE_DSK) venv

bench-controllers: $(BUILD)/pdp11 $(BUILD)/lockstep-coordinator $(BUILD)/barrier-bench venv  ## the five machines of issue 21: aggregate rate at full speed, the lock-step's overhead
	@$(PY) -m harness.bench.controllers_bench
BENCHES += bench-controllers

test-controllers-long: $(CONTROLLERS_NEEDS)  ## the long five-machine runs: a move twice (byte-identical), a kill during a move, the rack switched off and on at sim> during a move (not in make test)
	@CONTROLLERS_LONG=1 $(PY) -m pytest -q -n0 tests/controllers/test_lockstep_long.py tests/controllers/test_five_plant_long.py

controllers-runs: $(CONTROLLERS_NEEDS)  ## docs/servo.md's moves on both architectures: the table and figures of docs/controllers.md
	@$(PY) -m harness.figures.controllers_runs $(BUILD)/controllers-runs --figures docs/img/controllers

.PHONY: bench-controllers test-controllers-long controllers-runs
