# mk/disk.mk: RL02 block disk images (harness/blocks/disk.py, blocks/README.md).
#   build/robot.dsk   pristine image packed from blocks/*.txt (rebuilt when they change)
#   local/robot.dsk   the working disk of the interactive console: copied from the
#                     pristine image when missing, never overwritten by make (a
#                     user's edited blocks live there; neither a rebuild nor
#                     `make clean` touches local/)
#   make export-blocks [IMAGE=local/robot.dsk] [FROM=n] [TO=n] [FORCE=1]
#                     writes the image's non-blank blocks FROM..TO as blocks/NNNN.txt;
#                     a file that differs is only replaced with FORCE=1.
BLOCK_SRCS  := $(wildcard blocks/*.txt)
DISK_PY     := harness/blocks/blockfile.py harness/blocks/disk.py harness/commands/disk.py
PRISTINE_DSK := $(BUILD)/robot.dsk
WORK_DSK    := local/robot.dsk

# blocks/ itself is a prerequisite so that deleting a block file repacks the image.
$(PRISTINE_DSK): $(BLOCK_SRCS) blocks $(DISK_PY) | $(VENV)/.stamp
	@mkdir -p $(dir $@)
	@$(PY) -m harness disk pack blocks $@

# Order-only: a newer pristine image never replaces the working disk.
$(WORK_DSK): | $(PRISTINE_DSK)
	@mkdir -p $(dir $@)
	@cp $(PRISTINE_DSK) $@.tmp && mv $@.tmp $@
	@echo "==> working disk $@ created from $(PRISTINE_DSK) (make never overwrites it)"

IMAGE ?= $(WORK_DSK)
export-blocks: | $(VENV)/.stamp  ## blocks of IMAGE (default your working disk) to blocks/*.txt (FROM, TO, FORCE)
	@$(PY) -m harness disk export $(IMAGE) blocks \
	  $(if $(FROM),--from $(FROM)) $(if $(TO),--to $(TO)) $(if $(FORCE),--force)

disk: $(PRISTINE_DSK)  ## the pristine disk image build/robot.dsk from blocks/
work-disk: $(WORK_DSK)  ## your working disk local/robot.dsk (made once, never overwritten)

ALL_PRODUCTS += $(PRISTINE_DSK)
.PHONY: export-blocks disk work-disk
