#!/usr/bin/env bash
# A fuzzing campaign (make fuzz): every target of tests/fuzz under libFuzzer with ASan and
# UBSan, FUZZ_SECONDS each (default 60), two at a time when there are two cores; with
# FUZZ_RUNS=N each target stops after N executions instead (FUZZ_SECONDS still caps it). Seeds come
# from the project's own files (dae/, bez/, tests/io/data, tests/fuzz/regressions) and from
# OBJ and glTF conversions of the samples made by this build's meshedit; the corpus grows in
# BUILD/corpus/TARGET between runs. Crashes land in BUILD/artifacts/ (minimise one with
# `BUILD/tests/fuzz/fuzz_TARGET -minimize_crash=1 -runs=100000 FILE`, then add it to
# tests/fuzz/regressions/TARGET). Prints executions, seconds and coverage per target and
# exits 1 if any target found something.
set -euo pipefail
build=${1:-build-fuzz}
max_runs=${FUZZ_RUNS:--1}
if [ "$max_runs" != -1 ]; then
    seconds=${FUZZ_SECONDS:-86400}  # a run count alone: no time cap worth the name
else
    seconds=${FUZZ_SECONDS:-60}
fi
jobs=${FUZZ_JOBS:-$(nproc)}
targets=${FUZZ_TARGETS:-"collada obj off ply stl gltf bez bzc ops"}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

seed() {  # seed TARGET FILES...
    local dir="$build/corpus/$1"
    shift
    mkdir -p "$dir"
    for f in "$@"; do
        [ -f "$f" ] && cp -n "$f" "$dir/$(echo "$f" | tr '/' '_')" || true
    done
}
mkdir -p "$build/artifacts" "$build/logs" "$build/seeds"
seed collada dae/*.dae dae/*/*.dae tests/io/data/*.dae tests/fuzz/regressions/collada/*
seed obj tests/io/data/*.obj tests/fuzz/regressions/obj/*
seed off tests/fuzz/regressions/off/*
seed gltf tests/io/data/*.gltf tests/fuzz/regressions/gltf/*
seed bez bez/*.bez tests/io/data/*.bez tests/fuzz/regressions/bez/*
seed bzc bez/*.bzc tests/io/data/*.bzc tests/fuzz/regressions/bzc/*
seed ops tests/fuzz/regressions/ops/*
if [ -x "$build/src/cli/meshedit" ]; then
    for f in dae/cube.dae dae/icosahedron.dae dae/quadball.dae dae/bowl.dae dae/creased.dae; do
        name=$(basename "$f" .dae)
        "$build/src/cli/meshedit" convert "$f" "$build/seeds/$name.obj" >/dev/null 2>&1 || true
        "$build/src/cli/meshedit" convert "$f" "$build/seeds/$name.off" >/dev/null 2>&1 || true
        "$build/src/cli/meshedit" convert "$f" "$build/seeds/$name.glb" >/dev/null 2>&1 || true
        "$build/src/cli/meshedit" convert "$f" "$build/seeds/$name.gltf" >/dev/null 2>&1 || true
    done
    seed obj "$build"/seeds/*.obj
    seed off "$build"/seeds/*.off
    seed gltf "$build"/seeds/*.glb "$build"/seeds/*.gltf
fi
printf 'flip:0-6,split:0-1,loop\nloop:2\ncollapse:1-3,triangulate\ncrease:0-1,loop:1\n' |
    while read -r line; do printf '%s' "$line" > "$build/corpus/ops/seed_$(echo "$line" | md5sum | cut -c1-8)"; done

run_one() {
    local t=$1
    local log="$build/logs/$t.log"
    TMPDIR="${FUZZ_TMPDIR:-/dev/shm}" "$build/tests/fuzz/fuzz_$t" "$build/corpus/$t" \
        -dict="tests/fuzz/dict/$t.dict" -max_total_time="$seconds" -runs="$max_runs" -rss_limit_mb=2048 \
        -timeout=20 -max_len=262144 -print_final_stats=1 \
        -artifact_prefix="$build/artifacts/$t-" >"$log" 2>&1 || true
}
running=0
for t in $targets; do
    run_one "$t" &
    running=$((running + 1))
    if [ "$running" -ge "$jobs" ]; then
        wait -n
        running=$((running - 1))
    fi
done
wait

status=0
printf '%-8s %12s %8s %10s %s\n' target executions seconds coverage result
for t in $targets; do
    log="$build/logs/$t.log"
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
    if grep -qE 'ERROR: (AddressSanitizer|libFuzzer)|runtime error:|fuzz: |==ERROR' "$log"; then
        result="FOUND SOMETHING (see $log and $build/artifacts)"
        status=1
    else
        result=ok
    fi
    printf '%-8s %12s %8s %10s %s\n' "$t" "${runs:-?}" "${secs:-?}" "${cov:-?}" "$result"
done
exit $status
