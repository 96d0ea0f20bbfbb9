#!/bin/sh
# The viewer end to end (chapter 16): under Xvfb, open the viewer on a scene with its fixed
# camera for N frames of 1 sample per pixel, save the window's pixels, and compare them with
# `rtk render` of the same camera, size, seed and N samples per pixel. Both go through the
# same tone mapping to 8 bits, and render_pass makes N passes of 1 sample exactly the image of
# one pass of N, so the pixels must agree; TOLERANCE allows one 8-bit step for the display path.
# Also checks that without a display the viewer fails with a message that names -o, and that
# -fullscreen opens a window of the screen's size.
# usage: viewer_test.sh RTK COMPARE SCENE.ecs WORK_DIR
set -eu
rtk=$1 compare=$2 scene=$3 work=$4
frames=4
tolerance=1
mkdir -p "$work"
# Mesa's driver keeps allocations until exit; LeakSanitizer (sanitizer builds) would call them leaks.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
export ASAN_OPTIONS

# No display: a clear error (exit status 2) that says how to render to a file.
status=0
env -u DISPLAY -u WAYLAND_DISPLAY "$rtk" -c "$scene" -size 16 16 2>"$work/no_display.txt" || status=$?
cat "$work/no_display.txt"
if [ "$status" -ne 2 ] || ! grep -q -- "-o" "$work/no_display.txt"; then
  echo "FAIL: without a display the viewer should exit with 2 and explain -o (got $status)"
  exit 1
fi

if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "SKIP: xvfb-run is not installed (scripts/install-deps.sh installs xvfb and xauth)"
  exit 77
fi
set -- -c "$scene" -size 64 48 -seed 7 -threads 2
rm -f "$work/viewer.png" "$work/offline.png"
xvfb-run -a -s "-screen 0 640x480x24" "$rtk" "$@" -frames $frames -screenshot "$work/viewer.png"
"$rtk" "$@" -spp $frames -o "$work/offline.png"
"$compare" "$work/viewer.png" "$work/offline.png" $tolerance

# -fullscreen: the window, and so the screenshot, has the screen's size, whatever -size says.
rm -f "$work/fullscreen.png"
xvfb-run -a -s "-screen 0 640x480x24" "$rtk" "$@" -fullscreen -refine 0 -frames 2 -screenshot "$work/fullscreen.png"
size=$(python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); print('%dx%d' % struct.unpack('>II', d[16:24]))" "$work/fullscreen.png")
if [ "$size" != "640x480" ]; then
  echo "FAIL: a -fullscreen screenshot should be 640x480, the screen's size (got $size)"
  exit 1
fi
