# mk/pgo.mk: build/pdp11-guided, the simulator built profile-guided (gcc
# -fprofile-generate, a training run of the FORTH, -fprofile-use, with -O3 and
# link-time optimisation): the same sources as build/pdp11-plain (mk/devices.mk),
# the host code laid out for what the FORTH does.
#   1. build/obj/pgo-gen/: every object instrumented -> build/pdp11-train
#   2. the training run: mk/pgo-train.script on it (python -m harness run: boot,
#      1000 LOAD, a Sieve, a move on the servos, idle ticks; about a second)
#      writes the .gcda profiles beside the objects
#   3. build/obj/pgo-use/: every object again, guided by its profile -> build/pdp11-guided
# Reproducible: the training is deterministic (instruction counts, no host
# clock), so the same checkout gives the same profiles.
# build/pdp11 is a copy of build/pdp11-plain unless PGO=1: measured on the FORTH
# (a Sieve, `make bench-devices`) the guided build is 1.13 (-O2) to 1.21 (-O3,
# LTO) times as fast, short of the 1.3 that would pay for compiling the
# simulator twice more and a training run in every first build (about 15 s of
# CPU on this machine). Re-measured for issue 19 (a 200-pass Sieve by python -m
# harness run, CPU seconds, guided and plain in alternation): -O2 1.08, -O3 with
# LTO 1.11, the same without PIE 1.16, and with -fno-plt -fno-semantic-interposition
# -fipa-pta 1.10. Nearly 90 % of the plain build's time (perf) is SIMH's CPU core:
# sim_instr, and relocR, ReadW, ReadE, GeteaW (the 11/23's memory management
# relocating every access); guidance only inlines and lays out that code.
# Measured again on 2026-11-29, the host noisy (one variant's runs 27-45 M/s): the
# best-of figures gave 1.07-1.39, the round-by-round median 1.04-1.39; make test on
# the guided build passed the same 879 tests in 75-76 CPU-s against 82-85 (39.7-41.4
# s against 43.6-45.3 s wall), but the guided build from a clean tree takes 52 s of
# wall time (56 CPU-s). Every CI run and a newcomer's first make run (whose console
# is paced to the wall clock anyway) would pay that to save 3-5 s a make test: it
# stays opt-in (make PGO=1). The build is reproducible: rebuilt from clean, byte for
# byte the same. Since the plain build inlines relocR and ReadE itself (CPU_INLINE,
# mk/devices.mk), guided against plain on the Sieve: 1.03 (0.84-1.49), round by round.
# `make bench-devices` builds and times it.
PGO ?= 0
# both passes at -O3: the profile is read after the early inliner, whose choices
# the optimisation level changes (gripper.c's counters did not match at -O2/-O3)
PGO_OPT    := -O3
PGO_CFLAGS := $(PGO_OPT) -flto=auto
PGO_GEN := $(BUILD)/obj/pgo-gen
PGO_USE := $(BUILD)/obj/pgo-use
PGO_SIMH := $(patsubst %.c,%.o,$(SIMH_COMMON) $(SIMH_PDP11))
PGO_DEVS := $(patsubst $(DEV_DIR)/%.c,dev/%.o,$(DEV_GLUE))
PGO_PROFILE := $(PGO_GEN)/trained.stamp
PGO_SCRIPT := mk/pgo-train.script

# One object of the simulator in a flavour directory $(1) with extra flags $(2),
# after the shell command $(3):
# SIMH's files with SIMH's flags (pdp11_sys.c's table renamed, as for
# build/pdp11-plain), the devices with theirs.
define pgo_objects
$(1)/%.o: $$(SIMH_STAMP)
	@mkdir -p $$(dir $$@) && $(3)
	@$$(CC) $$(SIMH_CFLAGS) $(2) $$(if $$(filter PDP11/pdp11_sys,$$*),-Dsim_devices=stock_sim_devices) \
	  -c $$(SIMH_SRC)/$$*.c -o $$@
$(1)/dev/%.o: $$(DEV_DIR)/%.c $$(DEV_HDRS) $$(SIMH_STAMP) $$(KDF11_TABLE)
	@mkdir -p $$(dir $$@) && $(3)
	@$$(CC) $$(if $$(filter plant/plant plant/gripper,$$*),$$(PLANT_CFLAGS),$$(DEV_CFLAGS) $$(DEV_INCS) -I $$(GEN_DIR)) $(2) \
	  -c $$< -o $$@
endef

$(eval $(call pgo_objects,$(PGO_GEN),-fprofile-generate -fprofile-update=single $(PGO_OPT),true))
# guided: each object's profile copied beside it (gcc looks for it by the
# object's own path); a file the training never reached compiles as plain -O2
PGO_COPY = { cp $$(subst $(PGO_USE)/,$(PGO_GEN)/,$$(@:.o=.gcda)) $$(@:.o=.gcda) 2>/dev/null || true; }
$(eval $(call pgo_objects,$(PGO_USE),-fprofile-use -fprofile-correction -Wno-missing-profile $(PGO_CFLAGS),$(PGO_COPY)))
$(addprefix $(PGO_USE)/,$(PGO_SIMH) $(PGO_DEVS)): $(PGO_PROFILE)

$(BUILD)/pdp11-train: $(addprefix $(PGO_GEN)/,$(PGO_SIMH) $(PGO_DEVS))
	@echo "==> linking the instrumented simulator for the profile: $@"
	@$(CC) -fprofile-generate -o $@ $^ $(SIMH_LIBS)

# the profiles of one training run, from zero
$(PGO_PROFILE): $(BUILD)/pdp11-train $(PGO_SCRIPT) $(BUILD)/kernel.lda $(BUILD)/kernel.map \
                $(PRISTINE_DSK) | $(VENV)/.stamp
	@echo "==> training the profile-guided build on the FORTH ($(PGO_SCRIPT))"
	@find $(PGO_GEN) -name '*.gcda' -delete
	@rm -rf $(BUILD)/pgo-train && mkdir -p $(BUILD)/pgo-train
	@$(PY) -m harness run $(PGO_SCRIPT) --simulator $(abspath $(BUILD)/pdp11-train) --out $(BUILD)/pgo-train \
	  > /dev/null
	@touch $@

$(BUILD)/pdp11-guided: $(addprefix $(PGO_USE)/,$(PGO_SIMH) $(PGO_DEVS))
	@echo "==> linking the robot's PDP-11/23 simulator, profile-guided: $@"
	@$(CC) $(PGO_CFLAGS) -o $@ $^ $(SIMH_LIBS)

# the simulator every command runs
$(BUILD)/pdp11: $(BUILD)/pdp11-$(if $(filter 1,$(PGO)),guided,plain)
	@cp $< $@.tmp && mv $@.tmp $@
