# Quick start (README): `make demo` installs everything and runs the first task end to end with a video and a
# report; `make test` runs the checks (all of them, the slow local-model test included).
VENV ?= .venv
PY := $(VENV)/bin/python

.PHONY: setup demo test test-deps test-fast bench
setup:
	./scripts/setup.sh

demo: setup
	$(VENV)/bin/roboscript demo --out out/demo

# The tests need Open3D (perception), torch and transformers (detectors, tested on tiny models they build), and the
# slow ones llama.cpp (compiled on first install, about 5 minutes on 2 cores) and a small GGUF model.
test-deps:
	$(PY) -m pip install -q -e ".[dev,perception,detectors,slowtests]"

test: test-deps
	$(VENV)/bin/ruff check src tests benchmarks
	$(PY) -m pytest -q

test-fast:
	$(VENV)/bin/ruff check src tests benchmarks
	$(PY) -m pytest -q -m "not slow"

bench:
	$(PY) benchmarks/sim_speed.py
