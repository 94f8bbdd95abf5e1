# birdsim: every target sets itself up (virtual environment, packages) first.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
PYTEST := $(BIN)/python -m pytest

.PHONY: setup demo test test-slow test-all bench tables flight-tables report clean

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

# Rebuild the demo model's flight tables (finer grid; docs/flight.md): the seed bird's and the
# pigeon's (built for its reduced bird, so that its forces are in table units); ~2 min each.
FLIGHT_GRID := Fx=-0.2:0.3:21,Fz=-0.4:0:17,V=0:0.8:17
flight-tables: setup
	$(BIN)/birdsim tables build --model m3 --bird models/seed-bird.toml --grid "$(FLIGHT_GRID)" --out tables/seed-m3.npz --force
	$(BIN)/python -c "from birdsim.physics.bird import Bird; from birdsim.physics.units import reduced_bird; reduced_bird(Bird.from_toml('models/pigeon.toml')).to_toml('tables/pigeon-reduced.toml')"
	$(BIN)/birdsim tables build --model m3 --bird tables/pigeon-reduced.toml --grid "$(FLIGHT_GRID)" --out tables/pigeon-m3.npz --force; s=$$?; rm -f tables/pigeon-reduced.toml; exit $$s

# The dissertation's analysis as figures: report/index.html (a few minutes; QUICK=1 for coarse grids).
report: setup
	$(BIN)/birdsim report --out report --force $(if $(QUICK),--quick)

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
