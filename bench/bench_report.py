"""docs/performance.md from the records of one run of run_bench.py: the machine, the protocol,
the targets, and a table per job with MeshEdit's 1-thread and all-thread figures beside each
anchor and its threading (bench/README.md). Standard library only."""

import re

from bench_results import (BUILD_SIZES, NO_HUGE_PAGES, by_job, fmt_ms, fmt_num, is_meshedit,
                           ok_results, ratio_info, size_label, threading_of)
from bench_bound import bandwidth_section
from bench_targets import local_ops_table, targets_table

JOB_TITLES = {
    "stream_copy": "Memory bandwidth, STREAM copy `c = a` over 2^24 doubles (16 bytes an element; "
    "`gb_per_s` from the fastest repetition)",
    "stream_triad": "Memory bandwidth, STREAM triad `a = b + s·c` over 2^24 doubles (24 bytes an "
    "element; `gb_per_s` from the fastest repetition)",
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
    "loop_1m_attrs_1level": "Loop, 1 level, the same 1M-face torus carrying texture coordinates "
    "(two seam loops, face-varying, OpenSubdiv's default keep-corners rule) and RGBA colours: "
    "the cost of the attributes against `loop_1m_1level` (target ≤ 1.5×); MeshEdit only",
    "cc_1m_attrs_1level": "Catmull-Clark, 1 level, the same 1M-quad torus carrying texture "
    "coordinates and RGBA colours: the cost against `cc_1m_1level` (target ≤ 1.5×); MeshEdit "
    "only",
    **{f"cc_100k_levels_{k}": f"Catmull-Clark, {k} level(s), a closed torus of 99,825 faces "
       "(one quad in ten cut into two triangles)" for k in range(1, 4)},
    "qem_torus_1m_to_100k": "QEM simplification of the 1M-triangle torus to 100,000 faces; "
    "`hausdorff_pct`: the sampled symmetric Hausdorff distance to the input, % of its "
    "bounding-box diagonal (the same sampler for every impl)",
    "remesh_armadillo_208k": "Isotropic remeshing of armadillo (CGAL's demo data) "
    "Loop-subdivided once (208,000 triangles), L = its mean edge length, 3 iterations; "
    "`min_angle_deg`, `length_spread` (stddev / mean of the edge lengths) and `hausdorff_pct` "
    "by the same code for both",
    "remesh_bunny_75k": "The same on bunny00 (CGAL's demo data) as it is: 75,408 triangles, "
    "closed; `valence6_pct`: the share of inner vertices of valence 6, "
    "`valence4_or_less`: how many have 4 or fewer",
    "remesh_torus_80k": "The same on the 200 × 200 torus (80,000 triangles, every vertex of "
    "valence 6 before)",
    "smooth_1m_uniform": "Laplacian smoothing of a noisy 1M-triangle torus, 10 iterations, "
    "uniform weights, λ = 0.5 (OpenMesh's JacobiLaplaceSmootherT, C0); CGAL's closest "
    "explicit analogue, `tangential_relaxation` (each vertex to its neighbours' mean, the move "
    "kept in its tangent plane; `angle_and_area_smoothing` optimises angles and projects onto "
    "the input, further away); `ms_per_iteration`",
    "smooth_1m_implicit": "One implicit smoothing step (t = 1, cotangent weights) of the same "
    "torus; `solve_ms`: building the system and the conjugate-gradient solves; CGAL's "
    "`smooth_shape` (one backward Euler step of its cotangent Laplacian with the vertex areas "
    "as mass, BiCGSTAB + incomplete LU), its time step t × (area / vertices) / 2√3 so that the "
    "step is the same on this near-regular mesh",
    "qem_torus_attrs_1m_to_100k": "QEM of the same torus carrying texture coordinates (two "
    "seams) and vertex colours, attribute-aware (seams held, UV and colour quadrics): the cost "
    "of the attributes against `qem_torus_1m_to_100k` (target ≤ 1.5×); MeshEdit only",
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
    "stl_load_1m_binary": "Load the same torus as binary STL (each triangle its own three "
    "corners; both weld equal corners: MeshEdit by a hash of the position's bits, Assimp by "
    "JoinIdenticalVertices) into a mesh",
    "build_torus_1m": "Build the halfedge mesh of a 1M-triangle torus soup (the ordinary "
    "shape, for comparison with the rows below)",
    **{f"build_fan_hub_first_{n}": f"Build a {n}-triangle fan whose hub is vertex 0 (all its "
       "faces in one pairing bucket; 333 s for 1M before issue 14)" for n in BUILD_SIZES},
    **{f"build_polygon_{n}": f"Build one polygon of {n} corners (the repeated-corner check; "
       "208 s for 1M before issue 14)" for n in BUILD_SIZES},
    "compare_torus_1m_renumbered": "`meshedit compare`'s library call (match_topology() and "
    "measure_deviation()) on the 1M-triangle torus and a renumbered copy (vertices and faces "
    "shuffled, first corners rotated) at the same positions",
    "compare_torus_1m_moved": "The same with the copy moved by 0.001: the match starts from "
    "signatures, not positions, and the Hausdorff distance is sampled through two trees",
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
    "select_box_1m": "Box select through the mesh (Alt): the middle quarter of a 1280×800 view "
    "of the 1000 × 500 torus (1M triangles), elements_in_box(), one pass over the mesh",
    "select_box_visible_1m": "Box select of what the view shows, the release as the window pays "
    "it: the view's points (ShownPoints) built once, when B arms the box (`view_build_ms`), "
    "then in_box() over the middle quarter, each repetition",
    "select_box_visible_1m_cold": "The first region in a new view: ShownPoints built and "
    "in_box() read, each repetition",
    "select_lasso_visible_1m": "Lasso select of what the view shows, the release: a 64-point "
    "star over the middle quarter, in_lasso() on the view's points built once",
    "editor_simplify_1m": "D on bunny00 Loop-subdivided twice (1,206,530 triangles) to half: "
    "`core` simplify() and the garbage collection on a copy, `viewer` the D key as the window "
    "runs it, in the background (the worker's copy, the result put in as an undo step; no GPU; "
    "target: ≤ 1.2× core)",
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



def job_title(job):
    if job.endswith("_warm") and job[:-len("_warm")] in JOB_TITLES:
        return (JOB_TITLES[job[:-len("_warm")]] + " — **warm protocol**: memory reused across "
                "repetitions (one untimed repetition first, no malloc_trim, freed memory kept), "
                "so page faults are out of the times")
    if job in JOB_TITLES:
        return JOB_TITLES[job]
    m = re.fullmatch(r"fill_(bunny|armadillo)_(\w+)_(\d+)", job)
    if m:
        scan = {"bunny": "bunny00 Loop-subdivided " + ("three times" if m.group(2) == "5m"
                                                       else "twice"),
                "armadillo": "armadillo Loop-subdivided twice"}[m.group(1)]
        return (f"Hole filling: one hole of at least {m.group(3)} border edges (`hole_edges`: "
                f"what it came to) cut out of {scan} (CGAL's demo data), a disc of faces grown "
                "from a fixed seed in the order of their distance over the faces' centroids; "
                "MeshEdit's `fill_hole_fair` against CGAL's `triangulate_refine_and_fair_hole`, "
                "each given a halfedge of the hole's border (found untimed), both with their "
                "defaults (Liepa's density √2, bi-Laplacian fairing with "
                "cotangent weights), the fill call alone timed. Of the patch: `hausdorff_pct`, "
                "the symmetric Hausdorff distance to the faces cut away (100,000 points sampled "
                "by area on each side), `patch_to_original_pct` the patch's side alone, in % of "
                "the scan's bounding-box diagonal; `bounded_hausdorff_pct` and "
                "`bounded_patch_to_original_pct` the same by CGAL's bounded-error Hausdorff "
                "distance (within 0.1% of the true one); `min_angle_deg`, `patch_faces`, "
                "`patch_vertices` (new), `faired`")
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



MAIN_EXTRAS = ("peak_rss_mb", "bytes_per_face", "faces_out")
# Keys shown in their own columns, or only used to build them.
SHOWN = MAIN_EXTRAS + ("runs", "min_ms", "median_ms", "meshedit_threads", "all_threads",
                       "all_threads_min_ms", "all_threads_median_ms", "all_threads_runs")


def job_table(job, rows, info):
    """One job's table: every impl's min and median (MeshEdit's at 1 thread), MeshEdit's median
    at all threads and its speed-up, the ratio MeshEdit / impl on the 1-thread medians, each
    row's threads."""
    lines = [f"### `{job}`", "", job_title(job), ""]
    me, ratios, fastest, vs_fastest = ratio_info(rows)
    lines.append("| impl | threads | runs | min ms | median ms | median ms, all threads "
                 "| speed-up | MeshEdit / impl (median) | peak RSS MB | bytes/face | faces out "
                 "| other | status |")
    lines.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|")
    order = sorted(rows, key=lambda r: (r["impl"] != "meshedit", not is_meshedit(r["impl"]),
                                        r["impl"]))
    for r in order:
        if "median_ms" in r:
            ratio = "1" if r["impl"] == "meshedit" else (
                f"{ratios[r['impl']]:.3f}" if r["impl"] in ratios else "–")
            other = ", ".join(f"{k} {fmt_num(v)}" for k, v in sorted(r.items())
                              if k not in SHOWN and isinstance(v, (int, float)))
            every = r.get("all_threads_median_ms")
            all_cell = fmt_ms(every) if every is not None else "–"
            speedup = f"{r['median_ms'] / every:.2f}×" if every else "–"
            lines.append(
                f"| {r['impl']} | {threading_of(r)} | {r['runs']} | {fmt_ms(r['min_ms'])} "
                f"| {fmt_ms(r['median_ms'])} | {all_cell} | {speedup} | {ratio} "
                f"| {fmt_num(r.get('peak_rss_mb'))} | {fmt_num(r.get('bytes_per_face'))} "
                f"| {fmt_num(r.get('faces_out'))} | {other} | {r['status']} |")
        else:
            lines.append(f"| {r['impl']} | – | – | – | – | – | – | – | – | – | – "
                         f"| | {r['status']} |")
    lines.append("")
    if vs_fastest is not None:
        lines.append(f"MeshEdit (1 thread) / fastest anchor ({fastest}): **{vs_fastest:.3f}** "
                     + (f"(MeshEdit {1 / vs_fastest:.2f}× faster)." if vs_fastest < 1 else
                        f"(MeshEdit {vs_fastest:.2f}× slower)."))
        every = me.get("all_threads_median_ms") if me else None
        if every:
            anchor = ok_results(rows)[fastest]["median_ms"]
            lines.append(f"At all {me.get('all_threads', 'the')} threads: "
                         f"**{every / anchor:.3f}** of {fastest}.")
        lines.append("")
    for line in info:
        lines.append(f"Note: {line}")
        lines.append("")
    return lines


def render(args, records, notes, jobs_info, machine, started, wall, busy=None):
    """The whole report. `busy`: the 1-minute load average at start when it showed another
    busy process (the run was allowed with --allow-busy); the report then says so on top."""
    jobs = by_job(records)
    lines = [
        "# Performance",
        "",
        "Generated by `bench/run_bench.py` (`make bench`); do not edit by hand. MeshEdit against "
        "the libraries an editor would otherwise use, on identical inputs, in the same run "
        "(issue 6).",
        "",
    ]
    if busy is not None:
        lines += [f"**Measured on a busy machine**: the 1-minute load average was {busy:.2f} at "
                  f"the start (above `--max-load {args.max_load:g}`; run with `--allow-busy`). "
                  "Another process shared the cores, so every time below is indicative only.",
                  ""]
    lines += [
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
        f"--runs {args.runs} --timeout {args.timeout:.0f} --budget {args.budget:.0f} "
        f"--max-load {args.max_load:g}",
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
        "**Threads** (issue 38). MeshEdit's subdivision, normals, halfedge build and COLLADA "
        "parsing run in parallel (`include/meshedit/core/threads.h`); OpenMesh, CGAL, "
        "OpenSubdiv's Far, Assimp and meshoptimizer run on one thread. So every configuration "
        "that measures MeshEdit runs twice, in fresh processes: with `MESHEDIT_THREADS=1` — "
        "the *median ms* column, the ratios and every target, so that a lead is the "
        "algorithm's — and with `MESHEDIT_THREADS=0` (all cores), the *median ms, all "
        "threads* column and the speed-up (1 thread / all), which show the scaling. The "
        "*threads* column says how each row ran: `1 / N` for MeshEdit, the anchor's own "
        "threading otherwise. The results are the same bits on any number of threads.",
        "",
        "**Stable numbers.** A job whose median is under 20 ms repeats until its timed "
        "repetitions add up to 0.5 s (at most 2,000 of them; `bench_util.h`, "
        "`bench_python.py`), so the *runs* column can exceed "
        f"{args.runs}; min and median are over all of them. The run starts only when the "
        f"1-minute load average is at most {args.max_load:g} (it waits up to "
        f"{args.settle:.0f} s for a build to settle, then refuses unless `--allow-busy`, "
        "which marks this report).",
        "",
    ]
    if notes:
        lines += ["Notes on this run:", ""] + [f"- {n}" for n in notes] + [""]
    lines += ["## Targets (issue 6)", "",
              "Checked on MeshEdit's 1-thread medians (the anchors run on one thread).", ""]
    lines += targets_table(jobs) + [""]
    lines += bandwidth_section(jobs)
    lines += local_ops_table(jobs)
    lines += ["## Results per job", ""]
    for job, rows in jobs.items():
        lines += job_table(job, rows, jobs_info.get(job, []))
    return "\n".join(lines).rstrip() + "\n"


