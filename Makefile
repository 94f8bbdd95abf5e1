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

demo: setup
	$(BIN)/birdsim examples

test: setup
	$(PYTEST) -m "not slow" -n 2 -q

test-slow: setup
	$(PYTEST) -m slow -n 2 -q

test-all: setup
	$(PYTEST) -n 2 -q

bench: setup
	$(BIN)/python benchmarks/run.py

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
