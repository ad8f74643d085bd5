# Quick start (README): `make demo` installs everything and runs the first task end to end with a video and a
# report; `make test` runs the checks (all of them, the slow local-model test included).
VENV ?= .venv
PY := $(VENV)/bin/python

.PHONY: setup demo test test-deps test-fast bench
setup:
	./scripts/setup.sh

demo: setup
	$(VENV)/bin/roboscript demo --out out/demo

# The tests need Open3D (perception), torch and transformers (detectors, tested on tiny models they build),
# librealsense (its recorder and playback stand in for a camera), franky-sim (the FR3's model), and the
# slow ones llama.cpp (compiled once, about 5 minutes on 2 cores, then kept: scripts/install_llama.sh) and a small
# GGUF model.
test-deps:
	PY=$(PY) ./scripts/install_llama.sh
	$(PY) -m pip install -q -e ".[dev,perception,detectors,slowtests,ray,report,record,realsense,franky]"

# The suite runs on every core (pytest-xdist), a test file to a worker: a file's fixtures (a ROS master, a trial
# pool) are made once, and each trial still runs in processes of its own.
PYTEST := $(PY) -m pytest -q -n auto --dist loadfile

test: test-deps
	$(VENV)/bin/ruff check --no-cache src tests benchmarks
	$(VENV)/bin/lint-imports
	$(PYTEST)

test-fast:
	$(VENV)/bin/ruff check --no-cache src tests benchmarks
	$(VENV)/bin/lint-imports
	$(PYTEST) -m "not slow"

bench:
	$(PY) benchmarks/sim_speed.py
