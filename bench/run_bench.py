#!/usr/bin/env python3
"""Runs every benchmark configuration and writes docs/performance.md (bench/README.md).

Every (job, impl) configuration runs in a fresh process: `PROG --job J --impl I --runs N`.
The programs print `RESULT {json}` lines (and optional `INFO text` lines); this script
collects them and renders a table per job, the ratios MeshEdit / anchor, and the targets of
issue 6 with a "met?" column computed from the numbers of this run.

A program that is not built is skipped with a note. A program that answers `--list` with
lines "JOB IMPL" defines its own configurations; otherwise the defaults below are used.
Each configuration has a timeout (--timeout) and the whole run a budget (--budget): what is
left when the budget is spent is reported as skipped, never silently dropped.

MeshEdit's configurations run twice, at 1 thread and at all cores (MESHEDIT_THREADS); the
report's ratios and targets use the 1-thread figures. The run starts only on a quiet machine
(the 1-minute load average, --max-load), or with --allow-busy, which marks the report.

The report is rendered by bench_report.py and bench_targets.py; bench_machine.py describes
the machine. Standard library only. Progress goes to stderr.
"""

import argparse
import datetime
import json
import os
import shutil
import signal
import subprocess
import sys
import time

from bench_machine import hardware_threads, machine_description, threads_row, wait_for_quiet
from bench_report import render
from bench_results import (ALL_THREADS, ANCHOR_THREADING, NO_HUGE_PAGES, NO_HUGE_PAGES_JOBS,
                           ONE_THREAD, has_meshedit_rows, merge_thread_runs)

# Default configurations when a program does not answer --list.
DEFAULT_CONFIGS = {
    "bench_bandwidth": [("stream_copy", "machine"), ("stream_triad", "machine")],
    "bench_python": [("py_from_arrays_1m", i) for i in ("meshedit", "numpy_copy", "open3d")]
    + [("py_positions_1m", i) for i in ("view", "copy")]
    + [("py_flip_1000", i) for i in ("python_calls", "one_apply")]
    + [("py_read_ply_1m", i) for i in ("meshedit", "numpy", "open3d")],
    "bench_loop": [
        (job, impl)
        for job in ["loop_1m_1level"]
        + [f"loop_100k_levels_{k}" for k in range(1, 5)]
        + [f"loop_real_{name}_levels_{k}" for name in ("bunny00", "armadillo") for k in range(1, 4)]
        for impl in ("meshedit", "openmesh", "cgal", "opensubdiv_min", "opensubdiv_full")
    ] + [("loop_1m_attrs_1level", "meshedit")],
    "bench_ops": [
        (job, impl)
        for job in ("flips_1e6", "splits_1e6", "normals_6p4m")
        for impl in ("meshedit", "openmesh", "cgal")
    ],
    "bench_io_draw": [
        (job, impl)
        for job in ("collada_load_1m_triangles", "collada_load_1m_polylist", "ply_load_1m_binary",
                    "stl_load_1m_binary")
        for impl in ("meshedit", "assimp")
    ]
    + [("draw_1m_triangles", "all"),  # one run measures "meshedit" and "bare"
       ("pick_1m", "all")],  # one run measures "id_pass" and "bvh"
    "bench_build": [
        (f"build_{shape}_{size}", "meshedit")
        for shape in ("fan_hub_first", "polygon") for size in ("100k", "300k", "1m")
    ] + [("build_torus_1m", "meshedit")],
    "bench_smooth": [("smooth_1m_uniform", i) for i in ("meshedit", "openmesh", "cgal")]
    + [("smooth_1m_implicit", i) for i in ("meshedit", "cgal")],
    "bench_fill": [(f"fill_{scan}_{n}", impl)
                   for scan, sizes in (("bunny_1m", (10, 30, 100, 300, 1000)),
                                       ("bunny_5m", (2000,)),
                                       ("armadillo_832k", (10, 30, 100, 300)))
                   for n in sizes for impl in ("meshedit", "cgal")],
    "bench_compare": [(job, "meshedit") for job in ("compare_torus_1m_renumbered",
                                                    "compare_torus_1m_moved")],
    "bench_local_ops": [("dissolves_collapses_1e6_quad100k", "meshedit")]
    + [(f"local_ops_mix_{size}", "meshedit") for size in ("10k", "100k", "1m", "4m")]
    + [(f"local_ops_window_{size}", "meshedit") for size in ("10k", "100k", "1m", "4m")]
    + [(f"local_op_{op}_{size}", "meshedit") for op in ("dissolve_edge", "dissolve_vertex",
                                                        "collapse_edge", "collapse_face")
       for size in ("10k", "100k", "1m")]
    + [(f"extrude_all_faces_{size}", "meshedit") for size in ("10k", "100k", "1m")],
    "bench_editor": [("editor_edits_torus_1m", "all"), ("editor_edits_scan_1m", "all"),
                     ("editor_loop_1m", "core"), ("editor_loop_1m", "viewer"),
                     ("editor_simplify_1m", "core"), ("editor_simplify_1m", "viewer")],
    "bench_selection": [(job, "meshedit") for job in (
        "select_loop_1m", "select_ring_1m", "select_linked_1m", "select_grow_1m",
        "select_box_1m", "select_box_visible_1m", "select_box_visible_1m_cold",
        "select_lasso_visible_1m")],
    "bench_catmark": [
        (job, impl)
        for job in ["cc_1m_1level"] + [f"cc_100k_levels_{k}" for k in range(1, 4)]
        for impl in ("meshedit", "openmesh", "cgal", "opensubdiv_min", "opensubdiv_full")
    ] + [("cc_1m_attrs_1level", "meshedit")],
}
PROGRAMS = ["bench_bandwidth", "bench_loop", "bench_catmark", "bench_simplify", "bench_remesh",
            "bench_smooth", "bench_fill", "bench_ops", "bench_io_draw", "bench_build", "bench_local_ops", "bench_editor",
            "bench_selection", "bench_compare", "bench_python"]
# The warm protocol (bench_util.h, `--warm`): the same configurations again with every
# implementation reusing its memory across repetitions, so algorithm cost shows apart from
# page-fault cost. Reported under the job's name + "_warm"; the targets are checked on both.
WARM = "+warm"
WARM_JOBS = (["loop_1m_1level", "loop_1m_attrs_1level"] +
             [f"loop_100k_levels_{k}" for k in range(1, 5)] +
             ["cc_1m_1level", "cc_1m_attrs_1level"] + [f"cc_100k_levels_{k}" for k in range(1, 4)] +
             ["flips_1e6", "splits_1e6", "normals_6p4m", "editor_loop_1m"])

# Untimed preparation (input generation) run once before a program's configurations.
PREPARE = {"bench_io_draw": ["--generate"]}


def log(message):
    print(f"run_bench: {message}", file=sys.stderr, flush=True)



# ---------------------------------------------------------------------------------------------
# Running


def run_process(cmd, cwd, timeout, env=None):
    """Runs cmd in its own session; on timeout kills that process group. Returns
    (returncode or None on timeout, stdout, stderr, seconds)."""
    start = time.monotonic()
    proc = subprocess.Popen(
        cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        start_new_session=True, env=env)
    try:
        out, err = proc.communicate(timeout=timeout)
        return proc.returncode, out, err, time.monotonic() - start
    except subprocess.TimeoutExpired:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = proc.communicate()
        return None, out, err, time.monotonic() - start


def list_configs(program_path, name):
    rc, out, _, _ = run_process([program_path, "--list"], os.path.dirname(program_path), 20)
    if rc == 0:
        pairs = [tuple(line.split()) for line in out.splitlines() if line.strip()]
        if pairs and all(len(p) == 2 for p in pairs):
            return pairs, "--list"
    return DEFAULT_CONFIGS[name], "defaults in run_bench.py"


def parse_output(out):
    results, info = [], []
    for line in out.splitlines():
        if line.startswith("RESULT "):
            try:
                results.append(json.loads(line[len("RESULT "):]))
            except json.JSONDecodeError:
                info.append(f"unparsable RESULT line: {line[:120]}")
        elif line.startswith("INFO "):
            info.append(line[len("INFO "):].strip())
    return results, info


def matches(only, program, job):
    return not only or any(word in job or word in program for word in only)


def run_all(args):
    """Returns (records, notes, programs_seen). A record: dict with job, impl, status and the
    RESULT fields when there are any."""
    bench_dir = os.path.join(os.path.abspath(args.build), "bench")
    deadline = time.monotonic() + args.budget
    records, notes, jobs_info = [], [], {}
    every, skipped_all = [], 0  # MeshEdit's all-threads results; runs the budget left out
    plan = []
    for name in PROGRAMS:
        path = os.path.join(bench_dir, name)
        if not (os.path.isfile(path) and os.access(path, os.X_OK)):
            wanted = [c for c in DEFAULT_CONFIGS.get(name, []) if matches(args.only, name, c[0])]
            if wanted:
                notes.append(f"`{name}` is not built ({path} missing): its "
                             f"{len(wanted)} configuration(s) were skipped.")
                log(f"{name}: not built, skipping")
                for job, impl in wanted:
                    records.append({"job": job, "impl": impl, "status": f"{name} not built"})
            continue
        configs, source = list_configs(path, name)
        jobs_here = {job for job, _ in configs}
        configs += [(job, NO_HUGE_PAGES) for job in NO_HUGE_PAGES_JOBS if job in jobs_here]
        configs += [(job, impl + WARM) for job, impl in list(configs)
                    if job in WARM_JOBS and impl != NO_HUGE_PAGES]
        configs = [c for c in configs if matches(args.only, name, c[0])]
        if configs:
            log(f"{name}: {len(configs)} configuration(s) ({source})")
            plan.append((name, path, configs))

    total = sum(len(c) for _, _, c in plan)
    done = 0
    for name, path, configs in plan:
        if name in PREPARE:
            remaining = deadline - time.monotonic()
            log(f"{name}: preparing inputs ({' '.join(PREPARE[name])})")
            rc, out, err, secs = run_process([path] + PREPARE[name], os.path.dirname(path),
                                             max(1.0, min(args.timeout, remaining)))
            if rc != 0:
                notes.append(f"`{name} {' '.join(PREPARE[name])}` failed ({rc}): "
                             f"{err.strip().splitlines()[-1:] or ''}")
            else:
                log(f"{name}: inputs ready in {secs:.1f} s")
        for job, impl in configs:
            done += 1
            base = impl[:-len(WARM)] if impl.endswith(WARM) else impl
            settings = ([ONE_THREAD, ALL_THREADS] if has_meshedit_rows(name, base)
                        else [ONE_THREAD])
            for threads in settings:
                remaining = deadline - time.monotonic()
                how = "1 thread" if threads == ONE_THREAD else "all threads"
                label = f"[{done}/{total}] {job} {impl} at {how}"
                if remaining < 5:
                    if threads == ONE_THREAD:
                        records.append({"job": job, "impl": impl, "status": "skipped: time "
                                        f"budget of {args.budget:.0f} s spent"})
                    else:
                        skipped_all += 1
                    log(f"{label}: skipped (budget)")
                    continue
                results = run_config(path, job, impl, threads, args.runs,
                                     min(args.timeout, remaining), label, jobs_info)
                if threads == ONE_THREAD:
                    records += results
                else:
                    every += [r for r in results if r.get("status") == "ok"]
    if skipped_all:
        notes.append(f"{skipped_all} all-threads run(s) skipped (time budget spent): those "
                     "MeshEdit rows have the 1-thread figure only.")
    # Anchors measured in a MeshEdit process (the bare draw) keep their 1-thread record.
    every = [r for r in every if r["impl"] not in ANCHOR_THREADING]
    return merge_thread_runs(records, every), notes, jobs_info


def run_config(path, job, impl, threads, runs, timeout, label, jobs_info):
    """One configuration in a fresh process with MESHEDIT_THREADS=`threads`; returns its
    records (a record with only a status when it printed no RESULT)."""
    warm = impl.endswith(WARM)
    cmd = [path, "--job", job, "--impl", impl[:-len(WARM)] if warm else impl,
           "--runs", str(runs)] + (["--warm"] if warm else [])
    log(f"{label} (timeout {timeout:.0f} s) ...")
    env = dict(os.environ, MESHEDIT_THREADS=threads)
    rc, out, err, secs = run_process(cmd, os.path.dirname(path), timeout, env)
    results, info = parse_output(out)
    if info:
        jobs_info.setdefault(job, [])
        for line in info:
            if line not in jobs_info[job]:
                jobs_info[job].append(line)
    for r in results:
        r["status"] = "ok" if rc == 0 else f"exit {rc}"
    if rc is None:
        status = f"timed out after {timeout:.0f} s"
    elif rc != 0:
        last = err.strip().splitlines()[-1] if err.strip() else ""
        status = f"failed (exit {rc}): {last[:160]}"
    else:
        status = "ok"
    summary = ", ".join(f"{r['impl']} median {r['median_ms']:.1f} ms" for r in results)
    log(f"{label}: {status} in {secs:.1f} s" + (f" ({summary})" if summary else ""))
    return results or [{"job": job, "impl": impl, "status": status}]



def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build-bench", help="CMake build folder")
    parser.add_argument("--out", default="docs/performance.md", help="the Markdown report")
    parser.add_argument("--runs", type=int, default=5, help="repetitions per configuration")
    parser.add_argument("--timeout", type=float, default=240,
                        help="seconds per configuration before it is killed")
    parser.add_argument("--budget", type=float, default=900,
                        help="seconds for all configurations; the rest is reported as skipped")
    parser.add_argument("--only", default="",
                        help="comma-separated substrings of job or program names, e.g. "
                        "collada,draw")
    parser.add_argument("--max-load", type=float, default=0.5,
                        help="the 1-minute load average above which another process counts as "
                        "busy")
    parser.add_argument("--settle", type=float, default=180,
                        help="seconds to wait for the load to fall below --max-load at start")
    parser.add_argument("--allow-busy", action="store_true",
                        help="measure on a busy machine anyway; the report says so on top")
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be positive")
    args.only = [w for w in args.only.split(",") if w]
    if not os.path.isdir(args.build):
        parser.error(f"no build folder {args.build} (configure with MESHEDIT_BUILD_BENCH=ON)")

    load = wait_for_quiet(args.max_load, args.settle, log)
    busy = load if load is not None and load > args.max_load else None
    if busy is not None and not args.allow_busy:
        log(f"the 1-minute load average is {busy:.2f} (> --max-load {args.max_load:g}) after "
            f"{args.settle:.0f} s: another process is busy, so the times would not be "
            "comparable. Nothing was measured; stop it, or pass --allow-busy to measure anyway "
            "(the report then says so).")
        return 3
    started = datetime.datetime.now(datetime.timezone.utc)
    machine = machine_description(args.build) + [threads_row(hardware_threads())]
    t0 = time.monotonic()
    records, notes, jobs_info = run_all(args)
    wall = time.monotonic() - t0
    machine.append(("Load average at the end", " ".join(f"{x:.2f}" for x in os.getloadavg())))
    text = render(args, records, notes, jobs_info, machine, started, wall, busy)
    out_dir = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(out_dir, exist_ok=True)
    tmp = args.out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    shutil.move(tmp, args.out)
    ok = sum(1 for r in records if r.get("status") == "ok")
    log(f"wrote {args.out}: {ok} result(s), {len(records) - ok} not measured, "
        f"{wall:.0f} s of measurements")
    return 0


if __name__ == "__main__":
    sys.exit(main())
