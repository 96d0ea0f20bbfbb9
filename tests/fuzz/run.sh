#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for a bounded time,
# starting from the seed corpora in tests/fuzz/corpus_*/. Exits non-zero when a target finds
# a crash, a hang or a sanitizer report (libFuzzer then saves the input as crash-* / timeout-*
# in the current folder).
#
#   bash tests/fuzz/run.sh                    # 60 s per target (CI)
#   FUZZ_SECONDS=3600 bash tests/fuzz/run.sh  # an hour per target
#   bash tests/fuzz/run.sh -runs=100000       # extra arguments go to libFuzzer
#
# FUZZ_BUILD_DIR picks the build folder (default build-fuzz). New interesting inputs are kept
# in $FUZZ_BUILD_DIR/corpus_* so that a later run goes on from them; the seeds stay as they are.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${FUZZ_SECONDS:-60}
build_dir=${FUZZ_BUILD_DIR:-build-fuzz}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DRTK_FUZZ=ON -DRTK_BUILD_BENCH=OFF -DRTK_BUILD_BOOK=OFF >/dev/null
targets=(obj replay image mtl script xml)
cmake --build "$build_dir" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
for target in "${targets[@]}"; do
  corpus="$build_dir/corpus_$target"
  mkdir -p "$corpus"
  echo "fuzzing the $target reader for $seconds s"
  "$build_dir/tests/fuzz_$target" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 "$@" "$corpus" "tests/fuzz/corpus_$target"
done
echo "fuzzing: no failure"
