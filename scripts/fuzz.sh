#!/usr/bin/env bash
# A fuzzing campaign (make fuzz): every target of tests/fuzz under libFuzzer with ASan and
# UBSan, FUZZ_SECONDS each (default 60), FUZZ_JOBS at a time (default: one per core); with
# FUZZ_RUNS=N each target stops after N executions instead (FUZZ_SECONDS still caps it:
# `make fuzz FUZZ_RUNS=1000000` is the 10⁶ mode). A timeout or an out-of-memory input is
# saved and counted, and the target goes on from where it was (the corpus is kept) until its
# runs or seconds are used up; a crash ends the target. Inputs are at most FUZZ_MAX_LEN bytes
# (default 4096 for a reader, 2048 for .bez, 512 for an --ops list or a session: small
# inputs keep the rate up, and a longer list or more patches repeat what a shorter one
# reaches). libFuzzer's entropic schedule is off (FUZZ_ENTROPIC=1 turns it on): on a grown
# corpus its feature-frequency bookkeeping took 71% of fuzz_obj's time (clang 14), a
# quarter of the rate. Seeds come from the project's own files
# (dae/, bez/, tests/io/data, tests/fuzz/regressions) and from OBJ and glTF conversions of the
# samples made by this build's meshedit; the corpus grows in BUILD/corpus/READER between runs
# (a reader's round-trip and parse-only targets share it). Crashes land in BUILD/artifacts/
# (minimise one with `BUILD/tests/fuzz/fuzz_TARGET -minimize_crash=1 -runs=100000 FILE`, then
# add it to tests/fuzz/regressions/READER). libFuzzer's scratch files go to a folder of
# FUZZ_TMPDIR (default /dev/shm) removed at the end. Prints executions, seconds, rate,
# coverage, timeouts and out-of-memory inputs per target and exits 1 if any target found
# something.
set -euo pipefail
build=${1:-build-fuzz}
max_runs=${FUZZ_RUNS:--1}
if [ "$max_runs" != -1 ]; then
    seconds=${FUZZ_SECONDS:-86400}  # a run count alone: no time cap worth the name
else
    seconds=${FUZZ_SECONDS:-60}
fi
jobs=${FUZZ_JOBS:-$(nproc)}
# max_len TARGET: the longest input it is given (FUZZ_MAX_LEN for every target when set).
max_len() {
    case $1 in
        ops | session) echo "${FUZZ_MAX_LEN:-512}" ;;
        bez) echo "${FUZZ_MAX_LEN:-2048}" ;;
        *) echo "${FUZZ_MAX_LEN:-4096}" ;;
    esac
}
targets=${FUZZ_TARGETS:-"collada collada_parse obj obj_parse off off_parse ply ply_parse stl stl_parse
    gltf gltf_parse bez bzc ops session shader_log"}
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
seed session tests/fuzz/regressions/session/*
seed shader_log tests/fuzz/regressions/shader_log/*
seed ply tests/io/data/*.ply tests/fuzz/regressions/ply/*
seed stl tests/io/data/*.stl tests/fuzz/regressions/stl/*
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

scratch=$(mktemp -d "${FUZZ_TMPDIR:-/dev/shm}/meshedit-fuzz.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

# run_one TARGET: rounds of libFuzzer until the runs or seconds are used up; a round that
# ends on a timeout or out-of-memory input is counted and followed by another. Writes
# "executions seconds timeouts ooms" to BUILD/logs/TARGET.summary.
run_one() {
    local t=$1
    local reader=${t%_parse}
    local log="$build/logs/$t.log"
    local dict=()
    [ -f "tests/fuzz/dict/$reader.dict" ] && dict=(-dict="tests/fuzz/dict/$reader.dict")
    local runs_left=$max_runs secs_left=$seconds executions=0 timeouts=0 ooms=0
    local begin
    begin=$(date +%s)
    mkdir -p "$scratch/$t" "$build/corpus/$reader"
    : >"$log"
    while :; do
        TMPDIR="$scratch/$t" "$build/tests/fuzz/fuzz_$t" "$build/corpus/$reader" "${dict[@]}" \
            -max_total_time="$secs_left" -runs="$runs_left" -rss_limit_mb=2048 -timeout=20 \
            -max_len="$(max_len "$t")" -entropic="${FUZZ_ENTROPIC:-0}" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
            >"$log.round" 2>&1 || true
        cat "$log.round" >>"$log"
        local done_now
        done_now=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log.round" | tail -1)
        executions=$((executions + ${done_now:-0}))
        local elapsed=$(($(date +%s) - begin))
        if grep -q 'ERROR: libFuzzer: timeout' "$log.round"; then
            timeouts=$((timeouts + 1))
        elif grep -q 'ERROR: libFuzzer: out-of-memory' "$log.round"; then
            ooms=$((ooms + 1))
        else
            break  # done, or a crash
        fi
        secs_left=$((seconds - elapsed))
        [ "$max_runs" != -1 ] && runs_left=$((max_runs - executions))
        if [ "$secs_left" -le 0 ] || { [ "$max_runs" != -1 ] && [ "$runs_left" -le 0 ]; }; then
            break
        fi
    done
    rm -f "$log.round"
    echo "$executions $(($(date +%s) - begin)) $timeouts $ooms" >"$build/logs/$t.summary"
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
printf '%-14s %11s %8s %8s %9s %9s %5s %s\n' target executions seconds exec/s coverage timeouts ooms \
    result
for t in $targets; do
    log="$build/logs/$t.log"
    read -r runs secs timeouts ooms <"$build/logs/$t.summary" || true
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
    rate=$(( ${runs:-0} / (${secs:-0} > 0 ? ${secs:-1} : 1) ))
    if grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer)|ERROR: libFuzzer: (deadly signal|fuzz target exited)|runtime error:|^fuzz: ' "$log"; then
        result="CRASH (see $log and $build/artifacts)"
        status=1
    elif [ "${timeouts:-0}" -gt 0 ] || [ "${ooms:-0}" -gt 0 ]; then
        result="slow or hungry inputs in $build/artifacts"
        status=1
    else
        result=ok
    fi
    printf '%-14s %11s %8s %8s %9s %9s %5s %s\n' "$t" "${runs:-?}" "${secs:-?}" "$rate" "${cov:-?}" \
        "${timeouts:-?}" "${ooms:-?}" "$result"
done
exit $status
