#!/usr/bin/env bash
# `make run`: opens the viewer on the default sample; without a viewer or a display, renders
# the sample headless to a PNG instead, says where it is and how to get a window.
set -euo pipefail
build_dir=${1:-build}
sample=dae/teapot.dae
if [ -x "$build_dir/src/viewer/meshedit-view" ] && [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    echo "make run: the viewer on $sample (? in the window lists the keys; the programs are in" \
        "$build_dir/src/cli, or run make install)"
    exec "$build_dir/src/viewer/meshedit-view" "$sample"
fi
if [ -z "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    cat <<MSG
make run: no display (DISPLAY is not set), so no viewer window; rendering headless instead.
  For a window: run it from a desktop session, or over ssh -X (which sets DISPLAY), or on a
  virtual display:  Xvfb :1 & DISPLAY=:1 make run  (and look at it through x11vnc or xwd).
MSG
else
    echo "make run: the viewer was not built (configure with -DMESHEDIT_BUILD_VIEWER=ON)."
fi
out="$build_dir/teapot.png"
"$build_dir/src/headless/meshedit-render" "$sample" -o "$out" --size 1024x768
echo "make run: rendered $sample headless to $out"
