#!/usr/bin/env bash
# Runs the Embree comparison and writes its markdown table (bench/embree/results.md, for the
# book); the raw JSON stays in the build folder (bench/results.json, named after the table):
#
#   bash bench/embree/make_table.sh            # build dir "build", scenes from ../shared/scenes
#   BUILD_DIR=build-x RTK_SCENES=/path/a.obj,/path/b.obj bash bench/embree/make_table.sh
#   RESULTS=bench/embree/results_sse4.md bash bench/embree/make_table.sh --embree-isa=sse4.2 \
#       --benchmark_filter='(/embree|rtk:sse4:|rtk:bvh4.objectsplit:triangle4.moeller)'
#                                                # RTK's SSE4 kernels against Embree's SSE4.2 ones
#
# Extra arguments go to bench_embree (e.g. --rays=65536 --benchmark_min_time=0.2).
# The formatter is a CMake script (format_table.cmake): no python needed.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build_dir=${BUILD_DIR:-$root/build}
cmake --build "$build_dir" --target bench_embree -j"$(nproc)"
# The real meshes: a few of different character (meshes.txt), when the shared scene folder is
# there.
if [ -z "${RTK_SCENES:-}" ]; then
  shared="$root/../shared/scenes"
  list=""
  while read -r f; do
    [ -f "$shared/$f" ] && list="$list${list:+,}$shared/$f"
  done < "$here/meshes.txt"
  export RTK_SCENES="$list"
fi
results=${RESULTS:-$here/results.md}
json="$build_dir/bench/$(basename "$results" .md).json"
"$build_dir/bench/bench_embree" --benchmark_format=console --benchmark_out="$json" \
  --benchmark_out_format=json "$@"
cmake -DIN="$json" -DOUT="$results" -P "$here/format_table.cmake"
