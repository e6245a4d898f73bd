# Top-level Makefile: the 1983 Cartesian robot on an emulated PDP-11/23.
#   make        build everything (simulator, FORTH kernel, disk image)
#   make run    the interactive FORTH console
#   make test   the test suite (pytest, in parallel: a worker per core, plus one)
#   make bench  benchmarks, printing their figures
#   make help   every target, with what it does (the `## ...` after each target)
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

# The products build in parallel, a job per core (a fresh checkout's build: 65 s
# one job at a time, 38 s with two on this 2-core machine): `all` and make run's
# prerequisites are made by a sub-make with -j, unless make was given its own -j.
# What comes after them (the console, pytest, each benchmark) runs alone as before;
# -s: the recipes print their own progress, not make's "is up to date" for each goal.
JOBS ?= $(shell nproc)
IN_PARALLEL = $(MAKE) -s --no-print-directory $(if $(findstring jobserver,$(MAKEFLAGS)),,-j$(JOBS))

all:  ## build everything: the simulator, the FORTH kernel, the disk image (in parallel)
	@$(IN_PARALLEL) products
products: $(ALL_PRODUCTS)  ## what all builds, one job at a time unless make is given -j (all runs it with -j)

# One worker more than the cores: a worker waiting on a simulator's answer leaves
# its core to another. Bytecode is cached even where the environment says not to
# (PYTHONDONTWRITEBYTECODE), and written before the workers start, once: the
# tests start the harness in hundreds of processes.
TEST_WORKERS ?= $(shell echo $$(( $$(nproc) + 1 )))
test: all venv  ## the test suite (pytest, in parallel; browser sessions kept short), about 40 s on an idle 2-core host, as fast as its CPU (884 tests; README)
	@env -u PYTHONDONTWRITEBYTECODE $(PY) -m compileall -q harness tests > /dev/null
	@env -u PYTHONDONTWRITEBYTECODE $(PY) -m pytest -q -rs -n $(TEST_WORKERS) --dist loadscope tests

bench: all venv $(BENCHES)  ## every benchmark below, printing its figures

help:  ## this list
	@grep -hE '^[a-z][a-z0-9-]*:.*## ' $(MAKEFILE_LIST) | \
	  sed -E 's/^([a-z0-9-]+):.*## /\1\t/' | awk -F'\t' '{ printf "  make %-20s %s\n", $$1, $$2 }'

clean:  ## remove build/ (local/ and your working disk stay)
	rm -rf $(BUILD)

.PHONY: all products test bench clean run help
