# Quick start (README): `make demo` installs everything and renders a world; `make test` runs the checks.
VENV ?= .venv
PY := $(VENV)/bin/python

.PHONY: setup demo test bench
setup:
	./scripts/setup.sh

demo: setup
	$(VENV)/bin/roboscript worlds
	$(VENV)/bin/roboscript render world_1_table_sort --out out/world_1_table_sort
	$(VENV)/bin/roboscript render world_5_mug_to_cabinet --robot ur5e --out out/world_5_mug_to_cabinet_ur5e

test:
	$(VENV)/bin/ruff check src tests benchmarks
	$(PY) -m pytest -q

bench:
	$(PY) benchmarks/sim_speed.py
