# mk/devices.mk: build/pdp11, SIMH's PDP-11 simulator with the project's devices
# (pdp11-devices/: bus/ the DEC boards the program sees, plant/ the robot's
# physics and its glue, lab/ the lab bench's device, simh/ how they join SIMH),
# and build/plant_test and build/gripper_test (tests/devices/), the plant's
# axis physics and the gripper's mechanics tested alone.
#
# SIMH's files are compiled unpatched. The stock objects are shared with
# build/pdp11-stock, except pdp11_sys.c, compiled again with its device table
# renamed (stock_sim_devices): pdp11-devices/simh/machine_sys.c defines the table
# SIMH uses (see its header).
DEV_OBJ    := $(BUILD)/obj/devices
DEV_DIR    := pdp11-devices
DEV_KINDS  := bus plant lab simh
DEV_HDRS   := $(wildcard $(DEV_DIR)/*.h $(DEV_KINDS:%=$(DEV_DIR)/%/*.h))
DEV_GLUE   := $(wildcard $(DEV_KINDS:%=$(DEV_DIR)/%/*.c))
DEV_OBJS   := $(patsubst $(DEV_DIR)/%.c,$(DEV_OBJ)/%.o,$(DEV_GLUE))
DEV_INCS   := -I $(DEV_DIR) $(DEV_KINDS:%=-I $(DEV_DIR)/%)
ROBOT_SYS  := $(DEV_OBJ)/pdp11_sys_stock.o
ROBOT_SIMH_OBJS := $(filter-out $(STOCK_OBJ)/PDP11/pdp11_sys.o,$(STOCK_OBJS)) $(ROBOT_SYS)
# Our own code gets warnings; SIMH's headers need its flags.
DEV_CFLAGS := $(filter-out -w,$(SIMH_CFLAGS)) -Wall -Wno-unused-function
PLANT_CFLAGS := -std=c99 -O2 -g -Wall -Wextra

$(ROBOT_SYS): $(SIMH_STAMP)
	@mkdir -p $(dir $@)
	@$(CC) $(SIMH_CFLAGS) -Dsim_devices=stock_sim_devices -c $(SIMH_SRC)/PDP11/pdp11_sys.c -o $@

# the pure mechanics (no SIMH types): strict flags, tested alone
$(DEV_OBJ)/plant/plant.o $(DEV_OBJ)/plant/gripper.o: $(DEV_OBJ)/plant/%.o: $(DEV_DIR)/plant/%.c $(DEV_DIR)/plant/%.h
	@mkdir -p $(dir $@)
	@$(CC) $(PLANT_CFLAGS) -c $< -o $@

$(DEV_OBJ)/%.o: $(DEV_DIR)/%.c $(DEV_HDRS) $(SIMH_STAMP)
	@mkdir -p $(dir $@)
	@$(CC) $(DEV_CFLAGS) $(DEV_INCS) -c $< -o $@

$(BUILD)/pdp11: $(ROBOT_SIMH_OBJS) $(DEV_OBJS)
	@echo "==> linking the robot's PDP-11/23 simulator: $@"
	@$(CC) -o $@ $^ $(SIMH_LIBS)

$(BUILD)/plant_test: tests/devices/plant_test.c $(DEV_OBJ)/plant/plant.o
	@$(CC) $(PLANT_CFLAGS) -I $(DEV_DIR)/plant -o $@ $^ -lm

$(BUILD)/gripper_test: tests/devices/gripper_test.c $(DEV_OBJ)/plant/gripper.o
	@$(CC) $(PLANT_CFLAGS) -I $(DEV_DIR)/plant -o $@ $^ -lm

# pdp11-stock too: the reference the benchmark and tests/test_simh_stock.py use.
ALL_PRODUCTS += $(BUILD)/pdp11 $(BUILD)/plant_test $(BUILD)/gripper_test $(BUILD)/pdp11-stock

bench-devices: $(BUILD)/pdp11 $(BUILD)/pdp11-stock venv
	@$(PY) -m harness.bench.bench_devices
BENCHES += bench-devices
.PHONY: bench-devices
