# mk/disk.mk: the RL02 disk images (DESIGN.md section 1; tool: harness/blocks.py).
#   build/robot.dsk      the pristine image, packed from blocks/NNNN.fb
#   local/robot.dsk      the console's working disk (ROBOT_DISK, attached by
#                        build/robot.ini): made from the pristine image when it is
#                        missing, never overwritten by make, kept by make clean
#   make export-blocks   working disk -> blocks/NNNN.fb, to save terminal work in the
#                        repository (EXPORT_IMAGE=other.dsk to export another image)
# harness/blocks.py needs only Python's standard library, so no venv here.
ROBOT_DISK   ?= local/robot.dsk
BLOCK_FILES  := $(wildcard blocks/*.fb)
EXPORT_IMAGE ?= $(ROBOT_DISK)

$(BUILD)/robot.dsk: $(BLOCK_FILES) harness/blocks.py
	@mkdir -p $(BUILD)
	@python3 -m harness.blocks pack blocks $@

# order-only: a newer pristine image must not replace the user's blocks
$(ROBOT_DISK): | $(BUILD)/robot.dsk
	@python3 -m harness.blocks working $(BUILD)/robot.dsk $@

export-blocks:
	@python3 -m harness.blocks export $(EXPORT_IMAGE) blocks

ALL_PRODUCTS += $(BUILD)/robot.dsk $(ROBOT_DISK)
.PHONY: export-blocks

# instructions spent by the driver and the buffers (make bench)
bench-disk: all venv
	@$(PY) -m harness.disk_bench

BENCHES += bench-disk
.PHONY: bench-disk
