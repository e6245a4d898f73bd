# mk/run.mk: `make run`, for now the robot's PDP-11/23 (build/pdp11) with the
# machine configured (pdp11-devices/machine.ini), left at SIMH's sim> prompt.
# The FORTH console (build/robot.ini) takes its place when the kernel lands.
run: $(BUILD)/pdp11
	@$(BUILD)/pdp11 pdp11-devices/machine.ini
