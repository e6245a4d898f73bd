# mk/simh.mk: Debian's simh 3.8.1 source, and SIMH's stock PDP-11 simulator built
# from it (the reference the project's build/pdp11 is benchmarked against).
SIMH_DIR   := $(BUILD)/simh
SIMH_SRC   := $(SIMH_DIR)/simh-3.8.1
SIMH_STAMP := $(SIMH_SRC)/scp.c

# The files of SIMH's own makefile: common library + PDP-11 simulator.
SIMH_COMMON := scp.c sim_console.c sim_fio.c sim_timer.c sim_sock.c sim_tmxr.c \
               sim_ether.c sim_tape.c
SIMH_PDP11  := $(addprefix PDP11/,pdp11_fp.c pdp11_cpu.c pdp11_dz.c pdp11_cis.c \
  pdp11_lp.c pdp11_rk.c pdp11_rl.c pdp11_rp.c pdp11_rx.c pdp11_stddev.c pdp11_sys.c \
  pdp11_tc.c pdp11_tm.c pdp11_ts.c pdp11_io.c pdp11_rq.c pdp11_tq.c pdp11_pclk.c \
  pdp11_ry.c pdp11_pt.c pdp11_hk.c pdp11_xq.c pdp11_xu.c pdp11_vh.c pdp11_rh.c \
  pdp11_tu.c pdp11_cpumod.c pdp11_cr.c pdp11_rf.c pdp11_dl.c pdp11_ta.c pdp11_rc.c \
  pdp11_kg.c pdp11_ke.c pdp11_dc.c pdp11_io_lib.c)

# SIMH 3.8.1 predates gcc 10's -fno-common default; -fcommon is required.
SIMH_CFLAGS := -std=gnu99 -O2 -g -fcommon -U__STRICT_ANSI__ -D_GNU_SOURCE -DVM_PDP11 \
               -w -I $(SIMH_SRC) -I $(SIMH_SRC)/PDP11
SIMH_LIBS   := -lm -lrt

STOCK_OBJ := $(BUILD)/obj/stock
STOCK_OBJS := $(patsubst %.c,$(STOCK_OBJ)/%.o,$(SIMH_COMMON) $(SIMH_PDP11))

$(SIMH_STAMP):
	@bash mk/apt-need.sh dpkg-dev gcc make
	@bash mk/fetch-simh.sh $(SIMH_DIR)

$(STOCK_OBJ)/%.o: $(SIMH_STAMP)
	@mkdir -p $(dir $@)
	@$(CC) $(SIMH_CFLAGS) -c $(SIMH_SRC)/$*.c -o $@

$(BUILD)/pdp11-stock: $(STOCK_OBJS)
	@echo "==> linking SIMH's stock PDP-11 simulator: $@"
	@$(CC) -o $@ $^ $(SIMH_LIBS)

simh-source: $(SIMH_STAMP)  ## fetch SIMH 3.8.1's source (Debian's source package)
.PHONY: simh-source
