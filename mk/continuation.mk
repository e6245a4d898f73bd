# mk/continuation.mk: the project's continuation (issue 10): continuous-path
# motion and the gripper (blocks 1040-1053 and 1060-1062, docs/continuation.md).
#   make bench-continuation   Interrupt.Path's KDF11-A cost per tick (part of make bench)
#   make continuation-runs    the traces behind docs/continuation.md, in
#                             build/continuation/ (printed servo, and block 1030),
#                             and its figures, in docs/img/continuation-*.png
bench-continuation: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv  ## Interrupt.Path's KDF11-A cost per tick (docs/continuation.md)
	@$(PY) -m harness.bench.continuation_bench

continuation-runs: $(BUILD)/kernel.lda $(BUILD)/pdp11 $(BUILD)/robot.dsk venv  ## the continuation's traces, measurements and figures
	@$(PY) -m harness.figures.continuation_runs $(BUILD)/continuation --figures docs/img

BENCHES += bench-continuation
.PHONY: bench-continuation continuation-runs
