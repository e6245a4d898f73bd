# mk/devices.mk: build/pdp11, SIMH's PDP-11 simulator with the project's devices
# (pdp11-devices/: bus/ the DEC boards the program sees, plant/ the robot's
# physics and its glue, lab/ the lab bench's device, simh/ how they join SIMH),
# and build/plant_test and build/gripper_test (tests/devices/), the plant's
# axis physics and the gripper's mechanics tested alone.
#
# SIMH's files are compiled unpatched. The stock objects are shared with
# build/pdp11-stock, except pdp11_sys.c, compiled again with its device table
# renamed (stock_sim_devices): pdp11-devices/simh/machine_sys.c defines the table
# SIMH uses (see its header), and pdp11_cpu.c, compiled again with gcc allowed to
# inline larger functions (CPU_INLINE): the FORTH runs with the 11/23's memory
# management on, so every access goes through relocR, which -O2 leaves a call
# (perf: relocR 25 % of a scripted run, ReadE 10 %); inlined into sim_instr, an
# empty DO LOOP ran in 0.83 of the CPU time and the Sieve with the servo in 0.95
# (farm-bench, medians of pairs; 0.76-1.01 and 0.84-1.24: a noisy host), make test
# in about 5 % less; the same instructions executed, the same transcripts and traces.
# build/pdp11-timed is the one exception: the same simulator with a copy of
# pdp11_cpu.c patched by pdp11-devices/simh/pdp11_cpu_kdf11_time.patch, for SET
# CLK TIMED (11/23 time: SIMH's CPU loop has no hook for a per-instruction time;
# simh/kdf11_time.c says why and what). A separate binary because the patch's
# test costs every instruction even with the mode off (5 % on the Sieve,
# measured), and SIMH's files stay as shipped in the simulator everything else
# runs. The KDF11-A times come from harness/analysis/kdf11.py, as a generated C
# table.
DEV_OBJ    := $(BUILD)/obj/devices
DEV_DIR    := pdp11-devices
DEV_KINDS  := bus plant lab simh lockstep
DEV_HDRS   := $(wildcard $(DEV_DIR)/*.h $(DEV_KINDS:%=$(DEV_DIR)/%/*.h))
# lockstep/coordinator.c and barrier_bench.c are programs of their own, not devices
DEV_GLUE   := $(filter-out $(DEV_DIR)/lockstep/coordinator.c $(DEV_DIR)/lockstep/barrier_bench.c,\
                $(wildcard $(DEV_KINDS:%=$(DEV_DIR)/%/*.c)))
DEV_OBJS   := $(patsubst $(DEV_DIR)/%.c,$(DEV_OBJ)/%.o,$(DEV_GLUE))
DEV_INCS   := -I $(DEV_DIR) $(DEV_KINDS:%=-I $(DEV_DIR)/%)
ROBOT_SYS  := $(DEV_OBJ)/pdp11_sys_stock.o
CPU_INLINE := --param max-inline-insns-auto=200
ROBOT_CPU_PLAIN := $(DEV_OBJ)/pdp11_cpu_inlined.o
ROBOT_CPU  := $(DEV_OBJ)/pdp11_cpu_timed.o
CPU_PATCH  := $(DEV_DIR)/simh/pdp11_cpu_kdf11_time.patch
PATCHED_CPU := $(BUILD)/simh-patched/PDP11/pdp11_cpu.c
GEN_DIR    := $(BUILD)/gen
KDF11_TABLE := $(GEN_DIR)/kdf11_extra.h
ROBOT_SIMH_OBJS := $(filter-out $(STOCK_OBJ)/PDP11/pdp11_sys.o $(STOCK_OBJ)/PDP11/pdp11_cpu.o,\
                     $(STOCK_OBJS)) $(ROBOT_SYS) $(ROBOT_CPU_PLAIN)
TIMED_SIMH_OBJS := $(filter-out $(ROBOT_CPU_PLAIN),$(ROBOT_SIMH_OBJS)) $(ROBOT_CPU)
# Our own code gets warnings; SIMH's headers need its flags.
DEV_CFLAGS := $(filter-out -w,$(SIMH_CFLAGS)) -Wall -Wno-unused-function
PLANT_CFLAGS := -std=c99 -O2 -g -Wall -Wextra

$(ROBOT_SYS): $(SIMH_STAMP)
	@mkdir -p $(dir $@)
	@$(CC) $(SIMH_CFLAGS) -Dsim_devices=stock_sim_devices -c $(SIMH_SRC)/PDP11/pdp11_sys.c -o $@

$(PATCHED_CPU): $(SIMH_STAMP) $(CPU_PATCH)
	@mkdir -p $(dir $@)
	@bash mk/apt-need.sh patch
	@cp $(SIMH_SRC)/PDP11/pdp11_cpu.c $@.tmp
	@patch -s --no-backup-if-mismatch $@.tmp $(CPU_PATCH) && mv $@.tmp $@

# (this file is a prerequisite: it holds their flags)
$(ROBOT_CPU_PLAIN): $(SIMH_STAMP) mk/devices.mk
	@mkdir -p $(dir $@)
	@$(CC) $(SIMH_CFLAGS) $(CPU_INLINE) -c $(SIMH_SRC)/PDP11/pdp11_cpu.c -o $@

$(ROBOT_CPU): $(PATCHED_CPU) mk/devices.mk
	@mkdir -p $(dir $@)
	@$(CC) $(SIMH_CFLAGS) $(CPU_INLINE) -c $< -o $@

$(KDF11_TABLE): harness/analysis/kdf11.py harness/analysis/kdf11_table.py | $(VENV)/.stamp
	@$(PY) -m harness.analysis.kdf11_table $@

$(DEV_OBJ)/simh/kdf11_time.o: $(KDF11_TABLE)

# the pure mechanics and lock-step logic (no SIMH types): strict flags, tested alone
PURE_OBJS := $(addprefix $(DEV_OBJ)/plant/,plant.o plant_command.o gripper.o plant_row.o) \
             $(addprefix $(DEV_OBJ)/lockstep/,link.o quantum.o wire_io.o)
$(PURE_OBJS): $(DEV_OBJ)/%.o: $(DEV_DIR)/%.c $(DEV_HDRS)
	@mkdir -p $(dir $@)
	@$(CC) $(PLANT_CFLAGS) $(DEV_INCS) -c $< -o $@

$(DEV_OBJ)/%.o: $(DEV_DIR)/%.c $(DEV_HDRS) $(SIMH_STAMP)
	@mkdir -p $(dir $@)
	@$(CC) $(DEV_CFLAGS) $(DEV_INCS) -I $(GEN_DIR) -c $< -o $@

# build/pdp11-plain: the simulator, -O2 (build/pdp11 is a copy of it, or with
# PGO=1 of the profile-guided build/pdp11-guided: mk/pgo.mk).
$(BUILD)/pdp11-plain: $(ROBOT_SIMH_OBJS) $(DEV_OBJS)
	@echo "==> linking the robot's PDP-11/23 simulator (no profile guidance): $@"
	@$(CC) -o $@ $^ $(SIMH_LIBS)

$(BUILD)/pdp11-timed: $(TIMED_SIMH_OBJS) $(DEV_OBJS)
	@echo "==> linking the robot's PDP-11/23 simulator with KDF11-A time (SET CLK TIMED): $@"
	@$(CC) -o $@ $^ $(SIMH_LIBS)

$(BUILD)/plant_test: tests/devices/plant_test.c $(DEV_OBJ)/plant/plant.o
	@$(CC) $(PLANT_CFLAGS) -I $(DEV_DIR)/plant -o $@ $^ -lm

$(BUILD)/gripper_test: tests/devices/gripper_test.c $(DEV_OBJ)/plant/gripper.o
	@$(CC) $(PLANT_CFLAGS) -I $(DEV_DIR)/plant -o $@ $^ -lm

# The lock-step coordinator (pdp11-devices/lockstep/coordinator.c: the one plant of the five
# machines, docs/controllers.md) and its pure logic's test.
LOCKSTEP_PURE := $(filter $(DEV_OBJ)/plant/% $(DEV_OBJ)/lockstep/%,$(PURE_OBJS))
$(BUILD)/lockstep-coordinator: $(DEV_DIR)/lockstep/coordinator.c $(LOCKSTEP_PURE) $(DEV_HDRS)
	@$(CC) $(PLANT_CFLAGS) $(DEV_INCS) -o $@ $< $(LOCKSTEP_PURE) -lm

$(BUILD)/barrier-bench: $(DEV_DIR)/lockstep/barrier_bench.c $(DEV_OBJ)/lockstep/wire_io.o $(DEV_HDRS)
	@$(CC) $(PLANT_CFLAGS) $(DEV_INCS) -o $@ $< $(DEV_OBJ)/lockstep/wire_io.o

$(BUILD)/lockstep_test: tests/controllers/lockstep_test.c tests/controllers/world_status.h $(LOCKSTEP_PURE) $(DEV_HDRS)
	@$(CC) $(PLANT_CFLAGS) $(DEV_INCS) -o $@ $< $(LOCKSTEP_PURE) -lm

$(BUILD)/plant_command_test: tests/controllers/plant_command_test.c tests/controllers/world_status.h $(LOCKSTEP_PURE) $(DEV_HDRS)
	@$(CC) $(PLANT_CFLAGS) $(DEV_INCS) -o $@ $< $(LOCKSTEP_PURE) -lm

# pdp11-stock too: the reference the benchmark and tests/test_simh_stock.py use.
ALL_PRODUCTS += $(BUILD)/pdp11 $(BUILD)/pdp11-plain $(BUILD)/pdp11-timed $(BUILD)/plant_test $(BUILD)/gripper_test $(BUILD)/pdp11-stock \
                $(BUILD)/lockstep-coordinator $(BUILD)/lockstep_test $(BUILD)/plant_command_test $(BUILD)/barrier-bench

bench-devices: $(BUILD)/pdp11 $(BUILD)/pdp11-plain $(BUILD)/pdp11-guided $(BUILD)/pdp11-stock $(BUILD)/kernel.lda $(PRISTINE_DSK) venv  ## the C devices' cost: plain, guided and stock builds
	@$(PY) -m harness.bench.bench_devices
BENCHES += bench-devices
.PHONY: bench-devices

