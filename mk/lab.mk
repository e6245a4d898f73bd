# mk/lab.mk: the lab bench (python -m harness lab; docs/lab.md).
#   make lab              boot the FORTH and serve the page on 127.0.0.1 (prints the URL)
#   make lab SPEED=full   start at full speed (real, x10, full); PORT=n another port
#   make lab TIMED=1      on the 11/23's clock (SET CLK TIMED, build/pdp11-timed); the
#                         page's clock button switches it
#   make lab-assets       the page's libraries: xterm.js, pinned by harness/lab's
#                         package-lock.json, installed by npm ci into build/lab
#   make lab-browser      Debian's chromium and chromium-driver, for the browser tests
#   make test-browser     every browser session whole (make test runs a short one)
#   make test-lab-long    the longer browser session (not part of make test)
#   make bench-lab        the lab's cost: CPU at real pace, instruction rate at full speed
LAB_DIR   := $(BUILD)/lab
LAB_STAMP := $(LAB_DIR)/node_modules/.stamp
LAB_NEEDS := $(BUILD)/pdp11 $(BUILD)/pdp11-timed $(BUILD)/kernel.lda $(BUILD)/kernel.map $(LAB_STAMP) venv

$(LAB_STAMP): harness/lab/package.json harness/lab/package-lock.json
	@command -v npm >/dev/null || bash mk/apt-need.sh nodejs npm
	@echo "==> installing the lab page's libraries (npm ci, pinned: harness/lab/package-lock.json)"
	@mkdir -p $(LAB_DIR)
	@cp harness/lab/package.json harness/lab/package-lock.json $(LAB_DIR)/
	@cd $(LAB_DIR) && npm ci --no-audit --no-fund --loglevel=error
	@touch $@

lab-assets: $(LAB_STAMP)  ## the lab page's pinned npm libraries (npm ci into build/lab)
ALL_PRODUCTS += $(LAB_STAMP)

lab: $(LAB_NEEDS) $(WORK_DSK)  ## the lab bench in a browser (SPEED=full PORT=8100 TIMED=1): prints its URL
	@$(PY) -m harness lab $(if $(PORT),--port $(PORT)) $(if $(SPEED),--speed $(SPEED)) $(if $(TIMED),--timed)

# The browser tests skip, saying why, only where these cannot be installed.
lab-browser:  ## install Debian's chromium and chromium-driver for the lab's tests
	@bash mk/apt-need.sh chromium chromium-driver || echo "==> chromium could not be installed: the browser tests will skip"
test: lab-browser

test-browser: $(LAB_NEEDS) $(PRISTINE_DSK) $(BUILD)/lockstep-coordinator $(BUILD)/kernel-1103.lda lab-browser  ## every lab browser session whole, and the page of the five machines (make test keeps a short one)
	@LAB_BROWSER_FULL=1 $(PY) -m pytest -q -rs -n $(TEST_WORKERS) --dist loadscope tests/lab/test_browser.py \
	  tests/lab/test_browser_program.py tests/lab/test_browser_two_labs.py \
	  tests/controllers/test_five_plant_browser.py

test-lab-long: $(LAB_NEEDS) $(PRISTINE_DSK) lab-browser  ## the long lab browser session (not in make test)
	@LAB_LONG=1 $(PY) -m pytest -q tests/lab/test_long_session.py

bench-lab: $(LAB_NEEDS) $(PRISTINE_DSK) lab-browser  ## the lab's cost: CPU at real pace, instruction rate at full speed
	@$(PY) -m harness.bench.lab_bench
BENCHES += bench-lab
.PHONY: lab lab-assets lab-browser test-browser test-lab-long bench-lab
