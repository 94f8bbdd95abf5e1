# birdsim: every target sets itself up (virtual environment, packages) first.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
PYTEST := $(BIN)/python -m pytest

.PHONY: setup demo test test-slow test-all bench tables report clean

$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[test,plots]'
	@touch $(STAMP)

setup: $(STAMP)
	@sh scripts/setup_gl.sh

# the four preset manoeuvres in free flight (demo bird models/seed-bird.toml, demo model m3,
# tables/seed-m3.npz) into renders/ (regenerated: --force)
DEMO_MANOEUVRES := hover cruise take-off landing
demo: setup
	@for m in $(DEMO_MANOEUVRES); do \
	  $(BIN)/birdsim render $$m --model m3 --out renders/$$m-m3.mp4 --force || exit $$?; \
	done

test: setup
	$(PYTEST) -m "not slow" -n 2 -q

test-slow: setup
	$(PYTEST) -m slow -n 2 -q

test-all: setup
	$(PYTEST) -n 2 -q

bench: setup
	$(BIN)/python benchmarks/run.py

# Rebuild the shipped lookup tables tables/<model>.npz + .json (11^3 grid; a few minutes in all).
TABLE_MODELS := base m1 m2 m3 m4
tables: setup
	@for m in $(TABLE_MODELS); do \
	  $(BIN)/birdsim tables build --model $$m --out tables/$$m.npz --force || exit $$?; \
	done

# The dissertation's analysis as figures: report/index.html (a few minutes; QUICK=1 for coarse grids).
report: setup
	$(BIN)/birdsim report --out report --force $(if $(QUICK),--quick)

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
