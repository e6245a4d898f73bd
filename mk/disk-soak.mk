# mk/disk-soak.mk: is FLUSH durable? (harness/soak/disk_soak.py, README "Disk durability")
#   make soak-disk [CYCLES=100]   edit -> FLUSH -> UPDATE -> kill -9 -> reboot on one
#                                 image, CYCLES times (every 5th: kill -9 during
#                                 FLUSH); prints lost and corrupted blocks (both
#                                 must be 0; exit 1 otherwise). tests/disk runs 10.
CYCLES ?= 100
soak-disk: $(BUILD)/pdp11 $(BUILD)/kernel.lda $(BUILD)/robot.dsk venv  ## write, kill -9 during FLUSH, reread, CYCLES times: lost blocks (not in make test)
	@$(PY) -m harness.soak.disk_soak $(CYCLES)

.PHONY: soak-disk
