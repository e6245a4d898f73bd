# mk/run.mk: `make run`, the interactive FORTH console on the robot's PDP-11/23
# (python -m harness console): the simulator, the kernel, the Python venv and
# the working disk local/robot.dsk (made from build/robot.dsk when missing,
# never overwritten) are built first. Leave with BYE (blocks are flushed).
#   make run FAST=1      full speed while the FORTH works, the 11/23's pace while it waits for a key
#   make run TRACE=f.csv record the plant trace
#   make run TIMED=1     11/23 time: each instruction its KDF11-A time (SET CLK TIMED)
#   make run CONTROLLERS=4  the 11/23 and four LSI-11/03 axis controllers in lock-step
#                        (issue 21, docs/controllers.md; FAST and TRACE apply; LAB=1
#                        serves the lab's page of the five machines)
# What each run needs is built first, in parallel (IN_PARALLEL, Makefile); the
# console then runs alone, with the terminal to itself.
ifeq ($(CONTROLLERS),)
RUN_NEEDS := $(BUILD)/pdp11 $(BUILD)/pdp11-timed $(BUILD)/kernel.lda $(BUILD)/kernel.map $(WORK_DSK) venv
run: run-needs $(RUN_NEEDS)  ## the interactive FORTH console on your working disk (CONTROLLERS=4: five machines)
	@$(PY) -m harness console $(if $(FAST),--fast) $(if $(TRACE),--trace $(TRACE)) $(if $(TIMED),--timed)
else ifeq ($(CONTROLLERS),4)
RUN_NEEDS := $(BUILD)/pdp11 $(BUILD)/lockstep-coordinator $(BUILD)/kernel.lda $(BUILD)/kernel.map \
             $(BUILD)/kernel-1103.lda $(PRISTINE_DSK) $(WORK_DSK) venv
run: run-needs $(RUN_NEEDS)
	@$(PY) -m harness controllers launch $(if $(FAST),--fast) $(if $(TRACE),--trace $(TRACE)) $(if $(LAB),--lab)
else
run:
	@echo "make run CONTROLLERS=$(CONTROLLERS): the five-machine run has four controllers (CONTROLLERS=4)" >&2; exit 2
endif

run-needs:  ## what make run needs (CONTROLLERS=4: the five machines), built in parallel; make run starts with it
	@$(IN_PARALLEL) $(RUN_NEEDS)
.PHONY: run-needs
