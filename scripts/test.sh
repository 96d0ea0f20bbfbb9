#!/usr/bin/env bash
# README command 2: install what is missing, build everything and run every test with CTest.
# Extra arguments go to the CMake configuration (for example -DRTK_SANITIZE=address,undefined);
# BUILD_DIR picks the build folder (default: build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build_dir" -j"$(nproc)"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)"
