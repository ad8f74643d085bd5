#!/usr/bin/env bash
# llama.cpp's Python package (llama-cpp-python, at the version the slowtests extra pins) for the local-model test.
# It is compiled from source, about 5 minutes on 2 cores, so the wheel is built once per version, build flags and
# Python, and kept in a cache outside the clone ($ROBOSCRIPT_WHEEL_CACHE, default ~/.cache/roboscript/wheels) that
# every later set-up on the machine, a fresh clone's included, installs from.
#
# It is built for AVX2, not for the machine it is built on: llama.cpp's AMX kernels crash with a segmentation fault
# on some Xeons (Sapphire Rapids, seen in a VM here), and a wheel kept for one CPU may be installed on another.
# pip's own wheel cache is keyed by the source, not by CMAKE_ARGS (a cached native build, seen on fresh CI machines,
# would be taken over ours), so pip builds without its cache.
set -euo pipefail
cd "$(dirname "$0")/.."
PY="${PY:-.venv/bin/python}"
PIN="$(grep -o 'llama-cpp-python==[0-9.]*' pyproject.toml | head -1)"
FLAGS="${LLAMA_CMAKE_ARGS:--DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON}"
TAG="$("$PY" -c 'import sys; print(f"cp{sys.version_info[0]}{sys.version_info[1]}")')"
KEY="$(printf '%s\n' "$PIN" "$FLAGS" "$TAG" | sha256sum | cut -c1-16)"
CACHE="${ROBOSCRIPT_WHEEL_CACHE:-$HOME/.cache/roboscript/wheels}/llama-$KEY"

if ! ls "$CACHE"/llama_cpp_python-*.whl >/dev/null 2>&1; then
  echo "== compiling $PIN once (about 5 minutes on 2 cores); the wheel is kept in $CACHE"
  rm -rf "$CACHE.partial"
  mkdir -p "$CACHE.partial"
  CMAKE_ARGS="$FLAGS" "$PY" -m pip wheel -q --no-cache-dir --no-deps -w "$CACHE.partial" "$PIN"
  rm -rf "$CACHE"
  mv "$CACHE.partial" "$CACHE"  # whole or not at all: an interrupted build leaves no wheel to trust
else
  echo "== $PIN from the wheel kept in $CACHE"
fi
"$PY" -m pip install -q "$CACHE"/llama_cpp_python-*.whl
