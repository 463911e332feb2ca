# Quick start: `make demo` runs the main job, `make test` runs the test suite.
# Both create a local virtual environment in .venv on first use.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test test-extra lint models pictures renders study bench readme sysdeps clean

$(STAMP): pyproject.toml setup.py scripts/install-system-deps.sh scripts/make-venv.sh
	PYTHON=$(PYTHON) bash scripts/install-system-deps.sh
	bash scripts/make-venv.sh $(PYTHON) $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[test]"
	touch $(STAMP)

# The optional extras' own checks: MuJoCo Warp's parity (the gpu extra, ~400 MB) and the
# documentation site (the docs extra). Not part of the quick start; CI runs them.
EXTRA_STAMP := $(VENV)/.installed-extra
$(EXTRA_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e ".[test,gpu,docs]"
	touch $(EXTRA_STAMP)

# DEMO_ARGS: extra `wmr validate` options, e.g. DEMO_ARGS=--quick (3 draws a family,
# labelled quick) where only the set-up path is checked (scripts/ci-fresh-user.sh).
demo: $(STAMP)
	$(BIN)/wmr validate $(DEMO_ARGS)

test: $(STAMP)
	$(BIN)/ruff check src tests scripts
	$(BIN)/python -m pytest -m "not extra" -n auto

test-extra: $(EXTRA_STAMP)
	$(BIN)/python -m pytest -m extra

lint: $(STAMP)
	$(BIN)/ruff check src tests scripts

# Regenerate the checked-in MJCF files from the builders' defaults, the parameter tables
# and the Campion class table (docs/campion-classes.md).
models: $(STAMP)
	$(BIN)/python -m wmr_mujoco.docs_sync.export

# The pictures in models/*/README.md.
pictures: $(STAMP)
	$(BIN)/python -m wmr_mujoco.docs_sync.pictures

# The clips in renders/ shown in the README: every clip each registry entry lists.
renders: $(STAMP)
	$(BIN)/wmr render --all --out renders

# The design and fidelity-versus-cost studies in the model READMEs: omni3's roller design
# and peer table, the Whipple bicycle's eigenvalues, the free disc's settings and its
# leaning-start family against the contact, mecanum4's roller design; omni3's coasting
# energy budget and dynamics tables in docs/omni-dynamics.md.
study: $(STAMP)
	$(BIN)/python -m wmr_mujoco.bench.omni_study
	$(BIN)/python -m wmr_mujoco.bench.omni_energy_study
	$(BIN)/python -m wmr_mujoco.bench.whipple_study
	$(BIN)/python -m wmr_mujoco.bench.disc_study
	$(BIN)/python -m wmr_mujoco.bench.disc_leaning
	$(BIN)/python -m wmr_mujoco.bench.mecanum_study
	$(BIN)/python -m wmr_mujoco.bench.mecanum_phase
	$(BIN)/python -m wmr_mujoco.bench.mecanum_drift
	$(BIN)/python -m wmr_mujoco.bench.timestep_choice --seeds 0 1 2 3 --dampratios 0.5 0.6 0.8 1 --write

bench: $(STAMP)
	$(BIN)/wmr bench

# Paste reports/summary.md (make demo) and reports/bench.md (make bench) into docs/results.md and docs/benchmarks.md
# (a missing report changes nothing; `--only "validation results"` pastes one section).
readme: $(STAMP)
	$(BIN)/python -m wmr_mujoco.docs_sync.readme_sync

# The documentation site in site/: MkDocs, offline, warnings as errors; runs every
# tutorial (docs/tutorials/NN_*.py) while building (WMR_DOCS_EXECUTE=false skips that).
# (docs is phony: the folder docs/ must not stand for the target.)
.PHONY: docs tutorials
DOCS_STAMP := $(VENV)/.installed-docs
$(DOCS_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e ".[test,docs]"
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	NO_MKDOCS_2_WARNING=1 $(BIN)/mkdocs build --strict

# Every tutorial run top to bottom as a script, its exercise checked, its time printed.
tutorials: $(STAMP)
	$(BIN)/python -m pytest tests/docs/test_tutorials.py -q -s

sysdeps:
	PYTHON=$(PYTHON) bash scripts/install-system-deps.sh

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache src/*.egg-info
