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
# slow ones llama.cpp (compiled on first install, about 5 minutes on 2 cores) and a small GGUF model.
# llama.cpp is built for AVX2, not for the machine it is built on: its AMX kernels crash with a segmentation fault on
# some Xeons (Sapphire Rapids, seen in a VM here), and a wheel built for one CPU can be reused from pip's cache on another.
LLAMA_CMAKE_ARGS ?= -DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON

# pip's wheel cache is keyed by the source, not by CMAKE_ARGS: a cached native build (seen on fresh CI machines) would
# be taken over ours, so llama.cpp is built without the cache, at the version the slowtests extra pins.
LLAMA_PIN = $(shell grep -o 'llama-cpp-python==[0-9.]*' pyproject.toml | head -1)

test-deps:
	CMAKE_ARGS="$(LLAMA_CMAKE_ARGS)" $(PY) -m pip install -q --no-cache-dir "$(LLAMA_PIN)"
	$(PY) -m pip install -q -e ".[dev,perception,detectors,slowtests,ray,report,record,realsense,franky]"

test: test-deps
	$(VENV)/bin/ruff check --no-cache src tests benchmarks
	$(VENV)/bin/lint-imports
	$(PY) -m pytest -q

test-fast:
	$(VENV)/bin/ruff check --no-cache src tests benchmarks
	$(VENV)/bin/lint-imports
	$(PY) -m pytest -q -m "not slow"

bench:
	$(PY) benchmarks/sim_speed.py
