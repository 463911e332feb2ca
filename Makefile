# Quick start: `make demo` runs the main job, `make test` runs the test suite.
# Both create a local virtual environment in .venv on first use.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test lint models pictures renders study bench readme sysdeps clean

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

# Regenerate the checked-in MJCF files from the builders' defaults, the parameter tables
# and the README's Campion class table.
models: $(STAMP)
	$(BIN)/python -m wmr_mujoco.models.export

# The pictures in models/*/README.md.
pictures: $(STAMP)
	$(BIN)/python -m wmr_mujoco.models.pictures

# The clips in renders/ shown in the README.
renders: $(STAMP)
	$(BIN)/wmr render disc --scenario "sinusoidal steering" --out renders/disc.gif --width 200 --height 150 --fps 8 --duration 5
	$(BIN)/wmr render bicycle --scenario "lane change" --out renders/bicycle.gif --width 200 --height 150 --fps 8 --duration 5
	$(BIN)/wmr render tricycle --scenario "figure eight" --out renders/tricycle.gif --width 200 --height 150 --fps 8 --duration 12
	$(BIN)/wmr render omni3 --scenario "square with rotation" --out renders/omni3.gif --width 200 --height 150 --fps 8 --duration 10
	$(BIN)/wmr render mecanum4 --scenario "translate+rotate (ramp)" --out renders/mecanum4.gif --width 200 --height 150 --fps 8 --duration 10
	$(BIN)/wmr render whipple --scenario "push at 5 m/s" --out renders/whipple.gif --width 200 --height 150 --fps 8 --duration 8
	$(BIN)/wmr render whipple --scenario "push at 3 m/s" --out renders/whipple_fall.gif --width 200 --height 150 --fps 8 --duration 3
	$(BIN)/wmr render diffdrive --scenario "figure eight" --out renders/diffdrive.gif --width 200 --height 150 --fps 8 --duration 5
	$(BIN)/wmr render single_steer --scenario "slalom" --out renders/single_steer.gif --width 200 --height 150 --fps 8 --duration 4
	$(BIN)/wmr render double_steer --scenario "tight turn ±1 rad" --out renders/double_steer.gif --width 200 --height 150 --fps 8 --duration 3
	$(BIN)/wmr render disc_free --scenario "steady precession" --out renders/disc_free.gif --width 200 --height 150 --fps 8
	$(BIN)/wmr render disc_free --scenario "stability sweep" --out renders/disc_free_stability.gif --width 200 --height 150 --fps 8
	$(BIN)/wmr render omni3 --scenario "translate+rotate" --out renders/trails.png --width 480 --height 360 --fps 8

# The design and fidelity-versus-cost studies in the model READMEs: omni3's roller design
# and peer table, the Whipple bicycle's eigenvalues, the free disc's settings,
# mecanum4's roller design; omni3's coasting energy budget and dynamics tables in
# docs/omni-dynamics.md.
study: $(STAMP)
	$(BIN)/python -m wmr_mujoco.bench.omni_study
	$(BIN)/python -m wmr_mujoco.bench.omni_energy_study
	$(BIN)/python -m wmr_mujoco.bench.whipple_study
	$(BIN)/python -m wmr_mujoco.bench.disc_study
	$(BIN)/python -m wmr_mujoco.bench.mecanum_study

bench: $(STAMP)
	$(BIN)/wmr bench

# Paste reports/summary.md (make demo) and reports/bench.md (make bench) into README.md
# (a missing report changes nothing; `--only "validation results"` pastes one section).
readme: $(STAMP)
	$(BIN)/python -m wmr_mujoco.docs_sync.readme_sync

sysdeps:
	bash scripts/install-system-deps.sh

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache src/*.egg-info
