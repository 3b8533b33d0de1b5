#!/usr/bin/env bash
# `make run`: opens the viewer on the default sample once it exists.
set -euo pipefail
build_dir=${1:-build}
if [ -x "$build_dir/meshedit" ]; then
    exec "$build_dir/meshedit" dae/teapot.dae
fi
echo "make run: the viewer is not built yet (the halfedge core is; see README 'Status')."
echo "Run 'make test' to build and test the core."
