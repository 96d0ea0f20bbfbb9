#!/usr/bin/env bash
# README command 1: install what is missing, build RTK (Release), and run its main job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target rtk
build/apps/rtk info
# The main job: the Cornell box, rendered by the path tracer (chapter 14).
build/apps/rtk render -c scenes/cornell_box/cornell_box.ecs -spp 16 -o cornell_box.png
