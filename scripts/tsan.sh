#!/usr/bin/env bash
# ThreadSanitizer run of the parallel builders' tests (chapter 4's binned SAH builder and the
# builders that reuse it).
#
# TSan must see every synchronisation, and Debian's libtbb is not instrumented: linked with it,
# every hand-over of data through TBB's scheduler looks like a race. So this script fetches the
# same oneTBB 2021.8 sources Debian builds from (`apt-get source`, with a private source list:
# nothing on the system changes), builds libtbb with -fsanitize=thread, and builds RTK's tests
# against it. Work folder: $TSAN_DIR (default build-tsan).
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(realpath -m "${TSAN_DIR:-build-tsan}")
jobs=$(nproc)
mkdir -p "$work"

# Step 1: oneTBB's sources, from Debian's source package.
if [[ ! -d "$work/tbb-install" ]]; then
  apt_dir="$work/apt"
  mkdir -p "$apt_dir/lists/partial" "$work/tbb-src"
  echo "deb-src http://deb.debian.org/debian bookworm main" >"$apt_dir/sources.list"
  apt_options=(-q -o "Dir::Etc::SourceList=$apt_dir/sources.list" -o Dir::Etc::SourceParts=/dev/null
               -o "Dir::State::Lists=$apt_dir/lists" -o APT::Sandbox::User=root)
  apt-get "${apt_options[@]}" update >/dev/null
  (cd "$apt_dir" && apt-get "${apt_options[@]}" source --download-only onetbb >/dev/null)
  tar -xf "$apt_dir"/onetbb_*.orig.tar.xz -C "$work/tbb-src" --strip-components=1

  # Step 2: libtbb with TSan (the allocator and tests are not needed).
  cmake -S "$work/tbb-src" -B "$work/tbb-build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DTBB_SANITIZE=thread -DTBB_STRICT=OFF -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF \
        -DTBBMALLOC_BUILD=OFF -DTBBMALLOC_PROXY_BUILD=OFF -DCMAKE_INSTALL_PREFIX="$work/tbb-install" >/dev/null
  cmake --build "$work/tbb-build" -j"$jobs" >/dev/null
  cmake --install "$work/tbb-build" >/dev/null
fi

# Step 3: RTK's parallel-build tests with TSan, against that libtbb.
tbb_dir=$(dirname "$(find "$work/tbb-install" -name TBBConfig.cmake | head -n1)")
cmake -S . -B "$work/rtk" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRTK_SANITIZE=thread \
      -DTBB_DIR="$tbb_dir" -DRTK_BUILD_BENCH=OFF -DRTK_BUILD_BOOK=OFF >/dev/null
cmake --build "$work/rtk" --target ch04_tests -j"$jobs"

# Address-space randomisation off: some kernels place mappings where TSan's shadow memory goes.
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
setarch "$(uname -m)" -R "$work/rtk/chapters/04_sah/ch04_tests" \
  -tc='*threads*,*determinism*,*granularities*,*parallel partition*,*negative zeros*,*from the mesh*,*out of range*'
