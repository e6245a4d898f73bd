# Top-level Makefile: the 1983 Cartesian robot on an emulated PDP-11/23.
#   make        build everything (simulator, FORTH kernel, disk image)
#   make run    the interactive FORTH console
#   make test   the test suite (pytest, in parallel: a worker per core, plus one)
#   make bench  benchmarks, printing their figures
# Each part has its own fragment in mk/; fragments add to ALL_PRODUCTS and BENCHES.
SHELL := /bin/bash
BUILD := build
CC    ?= gcc
ALL_PRODUCTS :=
BENCHES :=
.DEFAULT_GOAL := all

include mk/simh.mk
include mk/python.mk
include $(filter-out mk/simh.mk mk/python.mk,$(wildcard mk/*.mk))

all: $(ALL_PRODUCTS)

# One worker more than the cores: a worker waiting on a simulator's answer leaves
# its core to another. Bytecode is cached even where the environment says not to
# (PYTHONDONTWRITEBYTECODE), and written before the workers start, once: the
# tests start the harness in hundreds of processes.
TEST_WORKERS ?= $(shell echo $$(( $$(nproc) + 1 )))
test: all venv
	@env -u PYTHONDONTWRITEBYTECODE $(PY) -m compileall -q harness tests > /dev/null
	@env -u PYTHONDONTWRITEBYTECODE $(PY) -m pytest -q -rs -n $(TEST_WORKERS) --dist loadscope tests

bench: all venv $(BENCHES)

clean:
	rm -rf $(BUILD)

.PHONY: all test bench clean run
