# birdsim: every target sets itself up (virtual environment, packages) first.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
PYTEST := $(BIN)/python -m pytest


.PHONY: web screenshots
.PHONY: setup demo test test-slow test-all bench tables report lint clean test-blender flight-tables

$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[test,plots,studio]'
	@touch $(STAMP)

setup: $(STAMP)
	@sh scripts/setup_gl.sh
	@sh scripts/setup_browser.sh

# the four preset manoeuvres in free flight (demo bird models/seed-bird.toml, demo model m3,
# tables/seed-m3.npz) into renders/ (regenerated: --force); 3 wingbeats per second of video
# keeps the demo under a minute (take-off and landing are 26 and 40 wingbeats)
# take-off and landing with legs (issue 25): the crouch, the jump, the touchdown, standing
DEMO_MANOEUVRES := hover cruise take-off landing
DEMO_LEGS := take-off landing
demo: setup
	@for m in $(DEMO_MANOEUVRES); do \
	  legs=$$(case " $(DEMO_LEGS) " in *" $$m "*) echo --legs;; esac); \
	  $(BIN)/birdsim render $$m --model m3 --beat-rate 3 $$legs --out renders/$$m-m3.mp4 --force || exit $$?; \
	done

test: setup
	$(PYTEST) -m "not slow" -n 2 -q

test-slow: setup
	$(PYTEST) -m slow -n 2 -q

test-all: setup
	$(PYTEST) -n 2 -q

# Optional, not part of `make test`: import the USD and BVH exports into Blender (bpy 4.5 LTS,
# Python 3.11, its own .venv-blender; the bpy wheel is ~370 MB) and check frames, rate,
# the body's position and the wingbeat (scripts/blender_check.py).
PYTHON311 ?= python3.11
BLENDER_VENV := .venv-blender
test-blender: setup
	@test -x $(BLENDER_VENV)/bin/python || $(PYTHON311) -m venv $(BLENDER_VENV)
	@$(BLENDER_VENV)/bin/python -c "import bpy" 2>/dev/null || $(BLENDER_VENV)/bin/python -m pip install -q 'bpy>=4.5,<4.6'
	@mkdir -p .blender-check
	$(BIN)/python scripts/blender_check.py prepare .blender-check
	$(BLENDER_VENV)/bin/python scripts/blender_check.py check .blender-check

# Rebuild the web bundle birdsim/studio/static/ (committed, with PROVENANCE.json) from web/
# (three.js and uPlot from the npm registry, pinned by web/package-lock.json; esbuild).
web:
	cd web && npm ci --no-audit --no-fund && npm run build

# The README's screenshots (docs/img/), taken by the browser tests.
screenshots: setup
	BIRDSIM_SCREENSHOTS=docs/img $(PYTEST) tests/test_studio_browser.py -q

bench: setup
	$(BIN)/python benchmarks/run.py

# Rebuild the shipped lookup tables tables/<model>.npz + .json (11^3 grid; a few minutes in all).
# m5 (issue 24, docs/tables.md): the incidence tie-break w_q 1e-4, a smoothing tolerance of
# 0.03, the regularising pass also starting from the neighbours' median and run to its fixed
# point (at most 32 rounds; 15 taken), then the plane moves. Its table was built under numpy's
# X86_V3 dispatch: NPY_DISABLE_CPU_FEATURES="X86_V4 AVX512_ICL AVX512_SPR" on an AVX-512 CPU.
TABLE_MODELS := base m1 m2 m3 m4
tables: setup
	@for m in $(TABLE_MODELS); do \
	  $(BIN)/birdsim tables build --model $$m --out tables/$$m.npz --force || exit $$?; \
	done
	$(BIN)/birdsim tables build --model m5 --incidence-weight 1e-4 --smooth-tol 0.03 --smooth-median \
	  --smooth-fixed-point --smooth-rounds 32 --smooth-planes --out tables/m5.npz --force

# Rebuild the demo model's flight tables (finer grid; docs/flight.md): the seed bird's and the
# pigeon's (tables build reduces a bird to its reduced bird: forces in table units); ~2 min each
# for m3; the pigeon's folding wing (m5, issue 24) took 11-25 min on the shared machine
# (468 CPU s; with m5's flap bound pi/2, 2026-12-02).
FLIGHT_GRID := Fx=-0.2:0.3:21,Fz=-0.4:0:17,V=0:0.8:17
flight-tables: setup
	$(BIN)/birdsim tables build --model m3 --bird models/seed-bird.toml --grid "$(FLIGHT_GRID)" --out tables/seed-m3.npz --force
	$(BIN)/birdsim tables build --model m3 --bird models/pigeon.toml --grid "$(FLIGHT_GRID)" --out tables/pigeon-m3.npz --force
	$(BIN)/birdsim tables build --model m5 --bird models/pigeon.toml --grid "$(FLIGHT_GRID)" --out tables/pigeon-m5.npz --force

# The dissertation's analysis as figures: report/index.html (a few minutes; QUICK=1 for coarse grids).
report: setup
	$(BIN)/birdsim report --out report --force $(if $(QUICK),--quick)

# Lint: ruff over the whole tree (settings in pyproject.toml, line length 100), checking only:
# it never rewrites a file (`ruff format` and `ruff check --fix` do, by hand).
LINT_PATHS := birdsim tests benchmarks scripts examples
lint: setup
	@test -x $(BIN)/ruff || $(BIN)/python -m pip install -q -e '.[lint]'
	$(BIN)/ruff check $(LINT_PATHS)
	$(BIN)/ruff format --check $(LINT_PATHS)

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
