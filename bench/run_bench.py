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

Standard library only. Progress goes to stderr.
"""

import argparse
import datetime
import json
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import time

# Default configurations when a program does not answer --list.
DEFAULT_CONFIGS = {
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
    ],
    "bench_ops": [
        (job, impl)
        for job in ("flips_1e6", "splits_1e6", "normals_6p4m")
        for impl in ("meshedit", "openmesh", "cgal")
    ],
    "bench_io_draw": [
        (job, impl)
        for job in ("collada_load_1m_triangles", "collada_load_1m_polylist", "ply_load_1m_binary")
        for impl in ("meshedit", "assimp")
    ]
    + [("draw_1m_triangles", "all"),  # one run measures "meshedit" and "bare"
       ("pick_1m", "all")],  # one run measures "id_pass" and "bvh"
    "bench_build": [
        (f"build_{shape}_{size}", "meshedit")
        for shape in ("fan_hub_first", "polygon") for size in ("100k", "300k", "1m")
    ] + [("build_torus_1m", "meshedit")],
    "bench_local_ops": [("dissolves_collapses_1e6_quad100k", "meshedit")]
    + [(f"local_ops_mix_{size}", "meshedit") for size in ("10k", "100k", "1m", "4m")]
    + [(f"local_ops_window_{size}", "meshedit") for size in ("10k", "100k", "1m", "4m")]
    + [(f"local_op_{op}_{size}", "meshedit") for op in ("dissolve_edge", "dissolve_vertex",
                                                        "collapse_edge", "collapse_face")
       for size in ("10k", "100k", "1m")]
    + [(f"extrude_all_faces_{size}", "meshedit") for size in ("10k", "100k", "1m")],
    "bench_editor": [("editor_edits_torus_1m", "all"), ("editor_edits_scan_1m", "all"),
                     ("editor_loop_1m", "core"), ("editor_loop_1m", "viewer")],
    "bench_catmark": [
        (job, impl)
        for job in ["cc_1m_1level"] + [f"cc_100k_levels_{k}" for k in range(1, 4)]
        for impl in ("meshedit", "openmesh", "cgal", "opensubdiv_min", "opensubdiv_full")
    ],
}
PROGRAMS = ["bench_loop", "bench_catmark", "bench_simplify", "bench_remesh", "bench_ops",
            "bench_io_draw", "bench_build", "bench_local_ops", "bench_editor", "bench_python"]
QEM_JOBS = ("qem_torus_1m_to_100k", "qem_bunny_1m_to_100k")
BUILD_SIZES = ("100k", "300k", "1m")
# bench_local_ops (issue 16): no anchor, no target; the cost per op at each size, side by side.
LOCAL_OPS = ("dissolve_edge", "dissolve_vertex", "collapse_edge", "collapse_face")
LOCAL_OPS_SIZES = ("10k", "100k", "1m", "4m")
# MeshEdit again with its huge-page hint off, for reference (not an anchor): what the hint is
# worth on this machine. Only where memory is allocated in the timed region.
NO_HUGE_PAGES = "meshedit_no_huge_pages"
NO_HUGE_PAGES_JOBS = ["loop_1m_1level"] + [f"loop_100k_levels_{k}" for k in range(1, 5)] + [
    "splits_1e6", "collada_load_1m_triangles"]
# The warm protocol (bench_util.h, `--warm`): the same configurations again with every
# implementation reusing its memory across repetitions, so algorithm cost shows apart from
# page-fault cost. Reported under the job's name + "_warm"; the targets are checked on both.
WARM = "+warm"
WARM_JOBS = (["loop_1m_1level"] + [f"loop_100k_levels_{k}" for k in range(1, 5)] +
             ["cc_1m_1level"] + [f"cc_100k_levels_{k}" for k in range(1, 4)] +
             ["flips_1e6", "splits_1e6", "normals_6p4m", "editor_loop_1m"])

# Untimed preparation (input generation) run once before a program's configurations.
PREPARE = {"bench_io_draw": ["--generate"]}

JOB_TITLES = {
    "py_from_arrays_1m": "Python: Mesh.from_arrays() of a 1M-triangle torus (numpy arrays in; "
    "numpy_copy: copying the two arrays, the floor of any conversion; open3d: a TriangleMesh, "
    "no halfedges)",
    "py_positions_1m": "Python: mesh.V on 1M triangles (view: no copy) against np.array(mesh.V)",
    "py_flip_1000": "Python: 1000 flips on a 100k-triangle torus, one mesh.flip() call each "
    "against one mesh.apply() of the same 1000 steps (parsed and run in C++); the difference / "
    "1000 is Python's cost per call",
    "py_read_ply_1m": "Python: reading a 1M-triangle binary PLY: meshedit.read() (with the "
    "halfedge build), numpy alone (the body as structured arrays, no mesh), Open3D",
    "loop_1m_1level": "Loop subdivision, 1 level, 1M-face torus (→ 4M faces)",
    "cc_1m_1level": "Catmull-Clark, 1 level, a closed torus of 1M quads (→ 4M quads)",
    **{f"cc_100k_levels_{k}": f"Catmull-Clark, {k} level(s), a closed torus of 99,825 faces "
       "(one quad in ten cut into two triangles)" for k in range(1, 4)},
    "qem_torus_1m_to_100k": "QEM simplification of the 1M-triangle torus to 100,000 faces; "
    "`hausdorff_pct`: the sampled symmetric Hausdorff distance to the input, % of its "
    "bounding-box diagonal (the same sampler for every impl)",
    "remesh_armadillo_208k": "Isotropic remeshing of armadillo (CGAL's demo data) "
    "Loop-subdivided once (208,000 triangles), L = its mean edge length, 3 iterations; "
    "`min_angle_deg`, `length_spread` (stddev / mean of the edge lengths) and `hausdorff_pct` "
    "by the same code for both",
    "qem_bunny_1m_to_100k": "QEM simplification of bunny00 (CGAL's demo data) Loop-subdivided "
    "twice (1,206,530 triangles) to 100,000 faces; `hausdorff_pct` as above",
    "flips_1e6": "1,000,000 random edge flips on the 100k torus",
    "splits_1e6": "1,000,000 random edge splits on the 100k torus",
    "normals_6p4m": "Area-weighted vertex normals, 6.4M faces "
    "(anchors weight differently: OpenMesh and CGAL do not weight by area the same way)",
    "collada_load_1m_triangles": "Load a 1M-triangle COLLADA `<triangles>` file into a mesh "
    "(MeshEdit: parse + halfedge build; Assimp: ReadFile with JoinIdenticalVertices | "
    "Triangulate)",
    "collada_load_1m_polylist": "Load a 1M-triangle COLLADA `<polylist>` with per-face normals "
    "(same impls)",
    "ply_load_1m_binary": "Load a 1M-triangle binary little-endian PLY (float x y z, `list "
    "uchar int vertex_indices`) into a mesh (same impls)",
    "build_torus_1m": "Build the halfedge mesh of a 1M-triangle torus soup (the ordinary "
    "shape, for comparison with the rows below)",
    **{f"build_fan_hub_first_{n}": f"Build a {n}-triangle fan whose hub is vertex 0 (all its "
       "faces in one pairing bucket; 333 s for 1M before issue 14)" for n in BUILD_SIZES},
    **{f"build_polygon_{n}": f"Build one polygon of {n} corners (the repeated-corner check; "
       "208 s for 1M before issue 14)" for n in BUILD_SIZES},
    "dissolves_collapses_1e6_quad100k": "1,000,000 random dissolves and collapses "
    "(dissolve_edge, dissolve_vertex, collapse, collapse_face) on the 100k-face quad-dominant "
    "torus; a fresh copy, untimed, whenever it falls below half its faces",
    "editor_edits_torus_1m": "The viewer's command layer (viewer::Editor) on the 1M-triangle "
    "torus: random F/S/C on a selected live edge (`command`: with the undo record, no GPU; "
    "`command_upload`: plus the renderer's buffer update), then undo and redo of every edit "
    "the history still holds; p50 is `median_ms`, `p99_ms` the 99th percentile",
    "editor_edits_scan_1m": "The same on bunny00 Loop-subdivided twice (1,206,530 triangles)",
    "editor_loop_1m": "Loop on the 1M torus: `core` loop_subdivide(), `viewer` the L key "
    "through viewer::Editor plus the upload of the new buffers (target: ≤ 2× core + upload)",
    "draw_1m_triangles": "Headless draw of a 1M-triangle torus at 1280×800 (llvmpipe via EGL, else OSMesa); MeshEdit's "
    "smooth Blinn-Phong renderer (which culls back faces of closed outward meshes) vs a trivial "
    "shader over the same vertex buffer (`bare`), and the trivial shader with back faces culled "
    "too (`bare_culled`, for reference); one process, glFinish after each frame",
    "pick_1m": "The element under the cursor on the same torus at 1280×800: 200 random pixels on "
    "the torus, picked by the ID pass (`id_pass`: `MeshRenderer::pick`, the pick shader over "
    "every triangle scissored to the pixel, read back) and on the CPU (`bvh`: `cpu_pick`, a ray "
    "into the face BVH, pick.frag's rules), one after the other at each position; `p50_ms`, "
    "`p99_ms` per pick, `build_ms` the BVH's build (median of 5), `same_answer` the positions "
    "where both agree",
}


def log(message):
    print(f"run_bench: {message}", file=sys.stderr, flush=True)


def size_label(size):
    """A size in a job name as the report writes it: 10k stays, 1m becomes 1M."""
    return size[:-1] + "M" if size.endswith("m") else size


def job_title(job):
    if job.endswith("_warm") and job[:-len("_warm")] in JOB_TITLES:
        return (JOB_TITLES[job[:-len("_warm")]] + " — **warm protocol**: memory reused across "
                "repetitions (one untimed repetition first, no malloc_trim, freed memory kept), "
                "so page faults are out of the times")
    if job in JOB_TITLES:
        return JOB_TITLES[job]
    m = re.fullmatch(r"loop_100k_levels_(\d+)", job)
    if m:
        return f"Loop subdivision, {m.group(1)} level(s), 100k-face torus"
    m = re.fullmatch(r"loop_real_(.+)_levels_(\d+)", job)
    if m:
        return f"Loop subdivision, {m.group(2)} level(s), real mesh {m.group(1)}"
    m = re.fullmatch(r"local_ops_mix_(\w+)", job)
    if m:
        return (f"100,000 random dissolves and collapses (the four-op mix) on the "
                f"{size_label(m.group(1))}-face quad-dominant torus, a fresh copy (untimed) "
                "after every faces/10 attempts")
    m = re.fullmatch(r"local_ops_window_(\w+)", job)
    if m:
        return (f"the four-op mix on the {size_label(m.group(1))}-face torus, elements drawn "
                "from a window of 1,000 faces' worth of indices sliding 2 faces per attempt")
    m = re.fullmatch(r"local_op_(\w+)_(\d+[km])", job)
    if m:
        return (f"100,000 random {m.group(1)} attempts on the {size_label(m.group(2))}-face "
                "quad-dominant torus, a fresh copy (untimed) after every faces/10 attempts")
    m = re.fullmatch(r"extrude_all_faces_(\w+)", job)
    if m:
        return (f"extrude_face on every face of the {size_label(m.group(1))}-face "
                "quad-dominant torus")
    return job


def command_output(args):
    try:
        return subprocess.run(args, capture_output=True, text=True, timeout=20).stdout
    except (OSError, subprocess.SubprocessError):
        return ""


# ---------------------------------------------------------------------------------------------
# Running


def run_process(cmd, cwd, timeout):
    """Runs cmd in its own session; on timeout kills that process group. Returns
    (returncode or None on timeout, stdout, stderr, seconds)."""
    start = time.monotonic()
    proc = subprocess.Popen(
        cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        start_new_session=True)
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
            remaining = deadline - time.monotonic()
            if remaining < 5:
                records.append({"job": job, "impl": impl,
                                "status": f"skipped: time budget of {args.budget:.0f} s spent"})
                log(f"[{done}/{total}] {job} {impl}: skipped (budget)")
                continue
            timeout = min(args.timeout, remaining)
            warm = impl.endswith(WARM)
            cmd = [path, "--job", job, "--impl", impl[:-len(WARM)] if warm else impl,
                   "--runs", str(args.runs)] + (["--warm"] if warm else [])
            log(f"[{done}/{total}] {job} {impl} (timeout {timeout:.0f} s) ...")
            rc, out, err, secs = run_process(cmd, os.path.dirname(path), timeout)
            results, info = parse_output(out)
            if info:
                jobs_info.setdefault(job, [])
                for line in info:
                    if line not in jobs_info[job]:
                        jobs_info[job].append(line)
            for r in results:
                r["status"] = "ok" if rc == 0 else f"exit {rc}"
                records.append(r)
            if rc is None:
                status = f"timed out after {timeout:.0f} s"
            elif rc != 0:
                last = err.strip().splitlines()[-1] if err.strip() else ""
                status = f"failed (exit {rc}): {last[:160]}"
            else:
                status = "ok"
            if not results or rc != 0:
                if not results:
                    records.append({"job": job, "impl": impl, "status": status})
            summary = ", ".join(f"{r['impl']} median {r['median_ms']:.1f} ms" for r in results)
            log(f"[{done}/{total}] {job} {impl}: {status} in {secs:.1f} s"
                + (f" ({summary})" if summary else ""))
    return records, notes, jobs_info


# ---------------------------------------------------------------------------------------------
# Machine description


def machine_description(build):
    lscpu = {}
    for line in command_output(["lscpu"]).splitlines():
        key, _, value = line.partition(":")
        lscpu[key.strip()] = value.strip()
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    mem = f"{int(line.split()[1]) / 1024 / 1024:.1f} GiB"
    except OSError:
        pass
    compiler, build_type, flags = "", "", ""
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            cache = dict(re.findall(r"^([A-Z_]+):[A-Z]+=(.*)$", f.read(), re.M))
        cxx = cache.get("CMAKE_CXX_COMPILER", "c++")
        compiler = (command_output([cxx, "--version"]).splitlines() or [cxx])[0]
        build_type = cache.get("CMAKE_BUILD_TYPE", "")
        flags = cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", "")
    except OSError:
        pass
    packages = []
    for pkg in ("libassimp-dev", "libopenmesh-dev", "libcgal-dev", "libosd-dev",
                "libegl-mesa0", "libosmesa6"):
        version = command_output(["dpkg-query", "-W", "-f=${Version}", pkg]).strip()
        if version:
            packages.append(f"{pkg} {version}")
    cores = lscpu.get("CPU(s)", str(os.cpu_count()))
    threads = lscpu.get("Thread(s) per core", "?")
    return [
        ("CPU", lscpu.get("Model name", platform.processor() or "unknown")),
        ("Logical CPUs", f"{cores} ({threads} thread(s) per core)"),
        ("Memory", mem),
        ("Kernel", f"{platform.system()} {platform.release()}"),
        ("Compiler", f"{compiler}; {build_type} ({flags})"),
        ("Anchor packages", ", ".join(packages)),
        ("Load average at start", " ".join(f"{x:.2f}" for x in os.getloadavg())),
    ]


# ---------------------------------------------------------------------------------------------
# Report


def fmt_ms(x):
    return f"{x:,.1f}" if x >= 10 else f"{x:.3f}"


def fmt_num(x):
    if x is None:
        return "–"
    if abs(x) >= 1e4 and float(x).is_integer():
        return f"{int(x):,}"
    return f"{x:.4g}"


def by_job(records):
    jobs = {}
    for r in records:
        jobs.setdefault(r["job"], []).append(r)
    return jobs


def ok_results(rows):
    return {r["impl"]: r for r in rows if "median_ms" in r}


def is_meshedit(impl):
    return impl == "meshedit" or impl.startswith("meshedit_")


def ratio_info(rows):
    """(meshedit median, {other impl: ratio}, fastest anchor name, ratio vs fastest). MeshEdit's
    own reference rows (meshedit_*) get a ratio but are never the fastest anchor."""
    res = ok_results(rows)
    me = res.get("meshedit")
    others = {k: v for k, v in res.items() if k != "meshedit"}
    anchors = {k: v for k, v in others.items() if not is_meshedit(k)}
    if me is None or not anchors:
        return me, {}, None, None
    ratios = {k: me["median_ms"] / v["median_ms"] for k, v in others.items() if v["median_ms"] > 0}
    fastest = min(anchors, key=lambda k: anchors[k]["median_ms"])
    return me, ratios, fastest, ratios.get(fastest)


MAIN_EXTRAS = ("peak_rss_mb", "bytes_per_face", "faces_out")


def job_table(job, rows, info):
    lines = [f"### `{job}`", "", job_title(job), ""]
    me, ratios, fastest, vs_fastest = ratio_info(rows)
    lines.append("| impl | runs | min ms | median ms | MeshEdit / impl (median) | peak RSS MB "
                 "| bytes/face | faces out | other | status |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---|---|")
    order = sorted(rows, key=lambda r: (r["impl"] != "meshedit", not is_meshedit(r["impl"]),
                                        r["impl"]))
    for r in order:
        if "median_ms" in r:
            ratio = "1" if r["impl"] == "meshedit" else (
                f"{ratios[r['impl']]:.3f}" if r["impl"] in ratios else "–")
            other = ", ".join(f"{k} {fmt_num(v)}" for k, v in sorted(r.items())
                              if k not in MAIN_EXTRAS and isinstance(v, (int, float))
                              and k not in ("runs", "min_ms", "median_ms"))
            lines.append(
                f"| {r['impl']} | {r['runs']} | {fmt_ms(r['min_ms'])} | {fmt_ms(r['median_ms'])} "
                f"| {ratio} | {fmt_num(r.get('peak_rss_mb'))} | {fmt_num(r.get('bytes_per_face'))} "
                f"| {fmt_num(r.get('faces_out'))} | {other} | {r['status']} |")
        else:
            lines.append(f"| {r['impl']} | – | – | – | – | – | – | – | | {r['status']} |")
    lines.append("")
    if vs_fastest is not None:
        lines.append(f"MeshEdit / fastest anchor ({fastest}): **{vs_fastest:.3f}** "
                     + (f"(MeshEdit {1 / vs_fastest:.2f}× faster)." if vs_fastest < 1 else
                        f"(MeshEdit {vs_fastest:.2f}× slower)."))
        lines.append("")
    for line in info:
        lines.append(f"Note: {line}")
        lines.append("")
    return lines


def subdivision_target_rows(jobs, scheme, big_job, levels_job, levels, big_what, levels_what):
    """The two "≤ 1/3 of the fastest anchor" rows of a subdivision scheme: one level of the
    big mesh, and every level of the 100k mesh (met only if every level is measured and
    met)."""
    rows = []
    _, _, fastest, r = ratio_info(jobs.get(big_job, []))
    rows.append((f"{scheme}, 1 level, {big_what}", "≤ 1/3 of the fastest anchor",
                 f"{r:.3f} of {fastest}" if r is not None else
                 f"not measured ({big_job}: MeshEdit or anchors missing)",
                 "n/a" if r is None else ("yes" if r <= 1 / 3 else "no")))
    parts, worst, missing = [], None, []
    for k in levels:
        _, _, fastest, r = ratio_info(jobs.get(levels_job.format(k), []))
        if r is None:
            missing.append(str(k))
            continue
        parts.append(f"L{k}: {r:.3f} of {fastest}")
        worst = r if worst is None else max(worst, r)
    if missing:
        parts.append(f"levels {', '.join(missing)} not measured")
    met = "n/a" if worst is None else ("yes" if worst <= 1 / 3 and not missing else
                                       ("no" if worst > 1 / 3 else "partly measured"))
    rows.append((f"{scheme}, levels {levels[0]}–{levels[-1]} on {levels_what}",
                 "≤ 1/3 of the fastest anchor", "; ".join(parts) or "not measured", met))
    return rows


def qem_target_rows(jobs):
    """Issue 17's QEM targets per input: ≥ 3× faster than OpenMesh and CGAL, ≤ 1.5×
    meshoptimizer's time, and a Hausdorff distance no worse than the best anchor's."""
    rows = []
    for job in QEM_JOBS:
        res = ok_results(jobs.get(job, []))
        me = res.get("meshedit")
        what = job.split("_")[1]
        if me is None:
            rows.append((f"QEM 1M → 100k ({what})", "see below", f"not measured ({job})", "n/a"))
            continue
        speed = []
        met = True
        for anchor, limit in (("openmesh", 1 / 3), ("cgal", 1 / 3), ("meshoptimizer", 1.5)):
            if anchor in res and res[anchor]["median_ms"] > 0:
                r = me["median_ms"] / res[anchor]["median_ms"]
                speed.append(f"{r:.3f} × {anchor}")
                met = met and r <= limit
            else:
                speed.append(f"{anchor} not measured")
                met = False
        anchors = {k: v["hausdorff_pct"] for k, v in res.items()
                   if not is_meshedit(k) and "hausdorff_pct" in v}
        if anchors and "hausdorff_pct" in me:
            best = min(anchors, key=anchors.get)
            quality = (f"Hausdorff {me['hausdorff_pct']:.4f}% vs {anchors[best]:.4f}% "
                       f"({best}, the best anchor)")
            met = met and me["hausdorff_pct"] <= anchors[best]
        else:
            quality, met = "Hausdorff not measured", False
        rows.append((f"QEM 1M → 100k ({what})",
                     "≤ 1/3 of OpenMesh's and CGAL's time, ≤ 1.5 × meshoptimizer's, Hausdorff "
                     "≤ the best anchor's", "; ".join(speed) + "; " + quality,
                     "yes" if met else "no"))
    return rows


def remesh_target_rows(jobs):
    """Issue 17's remeshing target: ≥ 3× faster than CGAL with min angle, edge-length spread
    and Hausdorff distance no worse."""
    res = ok_results(jobs.get("remesh_armadillo_208k", []))
    me, cgal = res.get("meshedit"), res.get("cgal")
    label = "isotropic remeshing, 3 iterations, 208k-face scan"
    target = "≤ 1/3 of CGAL's time; min angle, length spread, Hausdorff no worse"
    if me is None or cgal is None or not cgal["median_ms"] > 0:
        return [(label, target, "not measured (remesh_armadillo_208k)", "n/a")]
    r = me["median_ms"] / cgal["median_ms"]
    checks = [r <= 1 / 3,
              me.get("min_angle_deg", 0) >= cgal.get("min_angle_deg", 180),
              me.get("length_spread", 1e9) <= cgal.get("length_spread", 0),
              me.get("hausdorff_pct", 1e9) <= cgal.get("hausdorff_pct", 0)]
    measured = (f"{r:.3f} of CGAL; min angle {me.get('min_angle_deg', 0):.2f}° vs "
                f"{cgal.get('min_angle_deg', 0):.2f}°; spread {me.get('length_spread', 0):.3f} "
                f"vs {cgal.get('length_spread', 0):.3f}; Hausdorff "
                f"{me.get('hausdorff_pct', 0):.4f}% vs {cgal.get('hausdorff_pct', 0):.4f}%")
    return [(label, target, measured, "yes" if all(checks) else "no")]


def editor_target_rows(jobs, not_measured):
    """Issue 20: the viewer's command layer and renderer at a million faces (bench_editor)."""
    rows = []
    for job, mesh in (("editor_edits_torus_1m", "1M torus"), ("editor_edits_scan_1m",
                                                                "1.2M scan")):
        r = ok_results(jobs.get(job, []))
        if "command" not in r:
            rows.append((f"F/S/C, {mesh}", "p99 ≤ 1 ms", not_measured(job, "not run"), "n/a"))
            continue
        for impl, label, limit in (
                ("command", "F/S/C with undo record, no draw", 1.0),
                ("command_upload", "F/S/C plus GPU buffer update", 5.0),
                ("undo", "undo of such an edit", 1.0),
                ("undo_upload", "undo plus GPU buffer update", 5.0),
                ("redo", "redo of such an edit", 1.0),
                ("drag_move_upload", "one move of a vertex drag plus GPU buffer update", 5.0),
                ("extrude_move_upload", "one move of an interactive extrude plus GPU update",
                 5.0)):
            x = r.get(impl, {})
            if "p99_ms" in x:
                rows.append((f"{label}, {mesh}", f"p99 ≤ {limit:g} ms",
                             f"p99 {x['p99_ms']:.3f} ms, p50 {x['median_ms']:.3f} ms",
                             "yes" if x["p99_ms"] <= limit else "no"))
        c = r["command"]
        if "bytes_per_flip" in c:
            rows.append((f"undo memory per flip, {mesh}", "≤ 1 KiB",
                         f"{c['bytes_per_flip']:.0f} B (max {c.get('bytes_per_flip_max', 0):.0f})",
                         "yes" if c.get("bytes_per_flip_max", c["bytes_per_flip"]) <= 1024
                         else "no"))
        if "undo_steps_held" in c:
            held = c["undo_steps_held"]
            rows.append((f"200 undo steps of local edits, {mesh}", "all kept",
                         f"{held:.0f} kept, history {c.get('history_mib', 0):.2f} MiB",
                         "yes" if held >= 200 else "no"))
    for job, how in (("editor_loop_1m", ""), ("editor_loop_1m_warm", " (warm)")):
        loop = ok_results(jobs.get(job, []))
        if "core" in loop and "viewer" in loop and "command_ms" in loop["viewer"]:
            core = loop["core"]["median_ms"]
            v = loop["viewer"]
            rows.append((f"Loop in the viewer, 1M faces (command, without the upload){how}",
                         "≤ 2 × core Loop (+ upload)",
                         f"{v['command_ms']:.0f} ms vs core {core:.0f} ms = "
                         f"{v['command_ms'] / core:.2f}× (upload {v.get('upload_ms', 0):.0f} ms)",
                         "yes" if v["command_ms"] <= 2 * core else "no"))
        elif not how:
            rows.append(("Loop in the viewer, 1M faces", "≤ 2 × core Loop (+ upload)",
                         not_measured(job, "core or viewer missing"), "n/a"))
    return rows


def targets_table(jobs):
    rows = []

    def res(job):
        return ok_results(jobs.get(job, []))

    def not_measured(job, what):
        rows_ = jobs.get(job)
        if not rows_:
            return f"not measured ({job} not run)"
        statuses = sorted({r["status"] for r in rows_ if "median_ms" not in r})
        return f"not measured ({what}; {'; '.join(statuses) or 'missing impl'})"

    # Loop, 1 level of 1M, levels 1–4 on 100k.
    rows += subdivision_target_rows(jobs, "Loop", "loop_1m_1level", "loop_100k_levels_{}",
                                    range(1, 5), "1M → 4M faces", "100k faces")
    # Catmull-Clark (issue 17): 1 level of 1M quads, levels 1–3 on 100k mixed faces.
    rows += subdivision_target_rows(jobs, "Catmull-Clark", "cc_1m_1level", "cc_100k_levels_{}",
                                    range(1, 4), "1M quads → 4M", "100k mixed faces")
    rows += qem_target_rows(jobs)
    rows += remesh_target_rows(jobs)
    # The same subdivision targets under the warm protocol (memory reused: no page faults).
    if "loop_1m_1level_warm" in jobs:
        rows += [(r[0] + " (warm)",) + tuple(r[1:]) for r in subdivision_target_rows(
            jobs, "Loop", "loop_1m_1level_warm", "loop_100k_levels_{}_warm", range(1, 5),
            "1M → 4M faces", "100k faces")]
    if "cc_1m_1level_warm" in jobs:
        rows += [(r[0] + " (warm)",) + tuple(r[1:]) for r in subdivision_target_rows(
            jobs, "Catmull-Clark", "cc_1m_1level_warm", "cc_100k_levels_{}_warm", range(1, 4),
            "1M quads → 4M", "100k mixed faces")]
    # Bytes per face after Loop: the first Loop job where MeshEdit and CGAL both report it.
    loop_jobs = ["loop_1m_1level"] + sorted(j for j in jobs if j.startswith("loop_") and
                                            j != "loop_1m_1level")
    found = None
    for job in loop_jobs:
        rr = res(job)
        if "bytes_per_face" in rr.get("meshedit", {}) and "bytes_per_face" in rr.get("cgal", {}):
            found = (job, rr["meshedit"]["bytes_per_face"], rr["cgal"]["bytes_per_face"])
            break
    if found:
        job, me_b, cgal_b = found
        rows.append(("bytes per face after Loop", "≤ 0.85 × CGAL's",
                     f"{me_b:.1f} vs {cgal_b:.1f} = {me_b / cgal_b:.3f} ({job})",
                     "yes" if me_b <= 0.85 * cgal_b else "no"))
    else:
        rows.append(("bytes per face after Loop", "≤ 0.85 × CGAL's",
                     "not measured (no Loop job with bytes_per_face for meshedit and cgal)",
                     "n/a"))
    # Flips and splits: ≤ 0.5 × CGAL and ≤ 0.5 × OpenMesh.
    for job, label in (("flips_1e6", "1e6 random flips"), ("splits_1e6", "1e6 random splits"),
                       ("flips_1e6_warm", "1e6 random flips (warm)"),
                       ("splits_1e6_warm", "1e6 random splits (warm)")):
        if job.endswith("_warm") and job not in jobs:
            continue
        _, ratios, _, _ = ratio_info(jobs.get(job, []))
        parts = [f"{a}: {ratios[a]:.3f}" for a in ("cgal", "openmesh") if a in ratios]
        if len(parts) == 2:
            met = "yes" if ratios["cgal"] <= 0.5 and ratios["openmesh"] <= 0.5 else "no"
        else:
            met = "n/a" if not parts else "partly measured"
        rows.append((label, "≤ 0.5 × CGAL and ≤ 0.5 × OpenMesh",
                     "; ".join(parts) or not_measured(job, "MeshEdit or anchors missing"), met))
    # Normals.
    _, ratios, _, _ = ratio_info(jobs.get("normals_6p4m", []))
    _, warm_ratios, _, _ = ratio_info(jobs.get("normals_6p4m_warm", []))
    if "openmesh" in warm_ratios:
        rows.append(("area-weighted normals, 6.4M faces (warm)", "≤ 0.1 × OpenMesh",
                     f"{warm_ratios['openmesh']:.3f}",
                     "yes" if warm_ratios["openmesh"] <= 0.1 else "no"))
    if "openmesh" in ratios:
        rows.append(("area-weighted normals, 6.4M faces", "≤ 0.1 × OpenMesh",
                     f"{ratios['openmesh']:.3f}", "yes" if ratios["openmesh"] <= 0.1 else "no"))
    else:
        rows.append(("area-weighted normals, 6.4M faces", "≤ 0.1 × OpenMesh",
                     not_measured("normals_6p4m", "MeshEdit or OpenMesh missing"), "n/a"))
    # COLLADA and PLY.
    for job, label in (("collada_load_1m_triangles", "COLLADA load, 1M triangles"),
                       ("collada_load_1m_polylist",
                        "COLLADA load, 1M triangles, `<polylist>` + per-face normals (variant)"),
                       ("ply_load_1m_binary", "binary PLY load, 1M triangles")):
        _, ratios, _, _ = ratio_info(jobs.get(job, []))
        if "assimp" in ratios:
            speedup = 1 / ratios["assimp"]
            rows.append((label, "≥ 4 × faster than Assimp", f"{speedup:.2f}× faster",
                         "yes" if speedup >= 4 else "no"))
        else:
            rows.append((label, "≥ 4 × faster than Assimp",
                         not_measured(job, "MeshEdit or Assimp missing"), "n/a"))
    # Draw.
    _, ratios, _, _ = ratio_info(jobs.get("draw_1m_triangles", []))
    if "bare" in ratios:
        culled = (f" (for reference: {ratios['bare_culled']:.3f} × the bare draw with back faces "
                  "culled as MeshEdit culls them)" if "bare_culled" in ratios else "")
        rows.append(("draw 1M triangles headless", "≤ 1.2 × the bare draw",
                     f"{ratios['bare']:.3f} × bare{culled}",
                     "yes" if ratios["bare"] <= 1.2 else "no"))
    else:
        rows.append(("draw 1M triangles headless", "≤ 1.2 × the bare draw",
                     not_measured("draw_1m_triangles", "meshedit or bare missing"), "n/a"))

    # Picking (issue 20): the CPU pick's p99 per pick.
    picks = ok_results(jobs.get("pick_1m", []))
    if "bvh" in picks and "p99_ms" in picks["bvh"]:
        b = picks["bvh"]
        gpu = picks.get("id_pass", {})
        ref = (f"; ID pass p50 {gpu['p50_ms']:.0f} / p99 {gpu['p99_ms']:.0f} ms"
               if "p99_ms" in gpu else "")
        rows.append(("pick under the cursor, 1M triangles at 1280×800", "p99 ≤ 5 ms",
                     f"p99 {b['p99_ms']:.3f} ms, p50 {b['p50_ms']:.3f} ms (BVH built once per "
                     f"edit in {b.get('build_ms', 0):.0f} ms){ref}",
                     "yes" if b["p99_ms"] <= 5 else "no"))
    else:
        rows.append(("pick under the cursor, 1M triangles at 1280×800", "p99 ≤ 5 ms",
                     not_measured("pick_1m", "bvh missing"), "n/a"))

    rows += editor_target_rows(jobs, not_measured)

    # Loads that were once quadratic: the cost per face (per corner for the polygon) stays
    # flat from 100k to 1M.
    for shape, label in (("fan_hub_first", "build a fan around vertex 0"),
                         ("polygon", "build one huge polygon")):
        per = []
        for n in BUILD_SIZES:
            me = res(f"build_{shape}_{n}").get("meshedit", {})
            if "ns_per_face_or_corner" in me:
                per.append((n, me["ns_per_face_or_corner"]))
        target = "ns per face flat: 1M ≤ 2 × 100k"
        if len(per) == len(BUILD_SIZES):
            growth = per[-1][1] / per[0][1]
            rows.append((label + ", 100k / 300k / 1M", target,
                         " / ".join(f"{v:.0f}" for _, v in per) + f" ns (× {growth:.2f})",
                         "yes" if growth <= 2 else "no"))
        else:
            rows.append((label, target, not_measured(f"build_{shape}_1m", "a size missing"),
                         "n/a"))

    lines = ["| job | target | measured (median, MeshEdit / anchor) | met? |", "|---|---|---|---|"]
    lines += [f"| {a} | {b} | {c} | {d} |" for a, b, c, d in rows]
    return lines


def local_ops_table(jobs):
    """bench_local_ops (issue 16): ns per attempted op (per face for extrude) at each size, and
    the growth from the smallest to the largest size measured. No anchor, no target."""
    def ns(job, key):
        me = ok_results(jobs.get(job, [])).get("meshedit", {})
        return me.get(key)

    rows = [("the four-op mix", "local_ops_mix_{}", "ns_per_attempt"),
            ("the mix in a sliding window of 1,000 faces", "local_ops_window_{}",
             "ns_per_attempt")]
    rows += [(f"`{op}`", f"local_op_{op}_{{}}", "ns_per_attempt") for op in LOCAL_OPS]
    rows += [("`extrude_face`, every face (ns per face)", "extrude_all_faces_{}", "ns_per_face")]
    if not any(ns(pattern.format(size), key) is not None
               for _, pattern, key in rows for size in LOCAL_OPS_SIZES):
        return []
    head = " | ".join(size_label(n) for n in LOCAL_OPS_SIZES)
    lines = [
        "## Local operations in bulk (issue 16)",
        "",
        "MeshEdit only: no anchor does these in bulk, so there is no target ratio. Median ns per "
        "attempted op (refusals included: each op checks its predicate first) on a closed "
        "quad-dominant torus (one quad in ten cut into two triangles), random live elements, "
        "`std::mt19937` draws inside the timed region; the mesh is replaced by a fresh copy "
        "(untimed) after every faces/10 attempts, so every size sees the same relative wear. "
        "A local op's cost must not grow with the mesh: it rises only while the mesh outgrows "
        "the caches (`Mesh::bytes()` is 0.9 MB at 10k faces, 9 MB at 100k, 90 MB at 1M, 360 MB "
        "at 4M) and levels off past the last cache level: the 4M / 1M column is the flatness "
        "check. The sliding-window row draws the same mix from 1,000 faces' worth of indices "
        "that slide 2 faces per attempt (a band of the surface: the torus numbers every kind "
        "row by row), so the working set stays the same at every size: what is left is the "
        "operations' own cost, and its 1M / 10k column is the locality check. Extrude "
        "appends in index order and stays cache-friendly at every size.",
        "",
        f"| op | {head} | 1M / 10k | 4M / 1M |",
        "|---|" + "---:|" * (len(LOCAL_OPS_SIZES) + 2),
    ]

    def growth(a, b):
        return f"× {b / a:.2f}" if a and b else "–"

    for label, pattern, key in rows:
        values = dict((size, ns(pattern.format(size), key)) for size in LOCAL_OPS_SIZES)
        cells = ["–" if v is None else f"{v:,.0f}" for v in values.values()]
        lines.append(f"| {label} | {' | '.join(cells)} | {growth(values['10k'], values['1m'])} "
                     f"| {growth(values['1m'], values['4m'])} |")
    big = ok_results(jobs.get("dissolves_collapses_1e6_quad100k", [])).get("meshedit")
    lines.append("")
    if big:
        lines.append(
            f"1,000,000 random dissolves and collapses on the 100k mesh (a fresh copy whenever "
            f"it falls below half its faces): {big['median_ms']:,.0f} ms median, "
            f"**{big.get('ns_per_attempt', 0):,.0f} ns per attempt**, "
            f"{big.get('ns_per_applied', 0):,.0f} ns per applied op "
            f"({fmt_num(big.get('applied'))} applied, {fmt_num(big.get('refused'))} refused).")
        lines.append("")
    return lines


def render(args, records, notes, jobs_info, machine, started, wall):
    jobs = by_job(records)
    lines = [
        "# Performance",
        "",
        "Generated by `bench/run_bench.py` (`make bench`); do not edit by hand. MeshEdit against "
        "the libraries an editor would otherwise use, on identical inputs, in the same run "
        "(issue 6).",
        "",
        "## Machine",
        "",
        "| | |",
        "|---|---|",
    ]
    lines += [f"| {k} | {v} |" for k, v in machine]
    lines += [
        f"| Date | {started.strftime('%Y-%m-%d %H:%M UTC')} |",
        f"| Wall time of the measurements | {wall / 60:.1f} min |",
        "",
        "## How to reproduce",
        "",
        "    make bench",
        "",
        "installs the anchors (`scripts/install-deps.sh --bench`), builds `build-bench` in "
        "Release with `MESHEDIT_BUILD_BENCH=ON`, and runs",
        "",
        f"    python3 bench/run_bench.py --build build-bench --out docs/performance.md "
        f"--runs {args.runs} --timeout {args.timeout:.0f} --budget {args.budget:.0f}",
        "",
        "Every (job, impl) configuration runs in a **fresh process** (`PROG --job J --impl I "
        f"--runs {args.runs}`), so page-fault and allocator warm-up costs are inside the "
        "numbers of every implementation alike. Inside that process the job is repeated "
        f"{args.runs} times; the table gives the minimum and the median. The headless draw is "
        "the exception by design: MeshEdit's renderer and the bare draw run in *one* process "
        "and GL context, frames interleaved, `glFinish` after each. Ratios are MeshEdit's "
        "median over the anchor's median (below 1: MeshEdit is faster). Inputs are generated "
        "or unpacked at bench time into the build folder, never committed.",
        "",
        "Every repetition starts cold: `malloc_trim(0)` after each untimed setup hands the "
        "memory an allocator kept from the previous repetition back to the system, so every "
        "implementation pays for the pages it writes, as in a fresh process. MeshEdit keeps "
        "big arrays in 2 MiB huge pages (`include/meshedit/core/memory.h`); the anchors use "
        f"4 KiB pages. The `{NO_HUGE_PAGES}` rows are MeshEdit with that hint off "
        "(`--no-huge-pages`): a reference, not an anchor, showing how much of each ratio the "
        "pages account for on this machine (a VM, where a page fault is expensive).",
        "",
        "The `_warm` jobs repeat the main anchor comparisons under the **warm protocol** "
        "(`--warm`, bench/bench_util.h): one untimed repetition first, no `malloc_trim`, glibc "
        "serving every allocation from a heap it never trims (`M_MMAP_MAX` 0) and MeshEdit's "
        "big-buffer mapper keeping freed buffers for the next of the same size — every "
        "implementation reuses memory it already faulted in, as a long-running program does, "
        "so those tables show the algorithms' cost without page faults. The targets are "
        "checked on both.",
        "",
    ]
    if notes:
        lines += ["Notes on this run:", ""] + [f"- {n}" for n in notes] + [""]
    lines += ["## Targets (issue 6)", ""] + targets_table(jobs) + [""]
    lines += local_ops_table(jobs)
    lines += ["## Results per job", ""]
    for job, rows in jobs.items():
        lines += job_table(job, rows, jobs_info.get(job, []))
    return "\n".join(lines).rstrip() + "\n"


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
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be positive")
    args.only = [w for w in args.only.split(",") if w]
    if not os.path.isdir(args.build):
        parser.error(f"no build folder {args.build} (configure with MESHEDIT_BUILD_BENCH=ON)")

    started = datetime.datetime.now(datetime.timezone.utc)
    machine = machine_description(args.build)
    t0 = time.monotonic()
    records, notes, jobs_info = run_all(args)
    wall = time.monotonic() - t0
    text = render(args, records, notes, jobs_info, machine, started, wall)
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
