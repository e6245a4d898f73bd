# mk/disk-bench.mk: instructions spent by the RL02 driver and the block buffers
# (harness/bench/disk_bench.py), part of make bench.
bench-disk: all venv  ## instructions the RL02 driver and the block buffers spend
	@$(PY) -m harness.bench.disk_bench

BENCHES += bench-disk
.PHONY: bench-disk
