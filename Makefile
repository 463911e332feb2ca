# Quick start: `make demo` runs the main job, `make test` runs the test suite.
# Both create a local virtual environment in .venv on first use.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test lint models sysdeps clean

$(STAMP): pyproject.toml scripts/install-system-deps.sh
	bash scripts/install-system-deps.sh
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[test]"
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/wmr validate

test: $(STAMP)
	$(BIN)/ruff check src tests scripts
	$(BIN)/python -m pytest

lint: $(STAMP)
	$(BIN)/ruff check src tests scripts

# Regenerate the checked-in MJCF files from the builders' defaults.
models: $(STAMP)
	$(BIN)/python -m wmr_mujoco.export

sysdeps:
	bash scripts/install-system-deps.sh

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache src/*.egg-info
