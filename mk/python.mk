# mk/python.mk: the project's Python virtual environment, pinned packages.
VENV := .venv
PY   := $(VENV)/bin/python

$(VENV)/.stamp: requirements.txt
	@bash mk/apt-need.sh python3-venv
	@echo "==> creating the Python virtual environment $(VENV) (pinned: requirements.txt)"
	@python3 -m venv $(VENV)
	@$(VENV)/bin/pip install -q --disable-pip-version-check -r requirements.txt
	@touch $@

venv: $(VENV)/.stamp  ## the pinned Python environment .venv (requirements.txt)
.PHONY: venv
