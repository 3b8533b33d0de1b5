"""What run_bench.py and its report share: job names, number formats, and reading the RESULT
records of a run (bench/README.md). Standard library only."""

# MeshEdit's rows run twice (issue 38): at 1 thread, the figure every table and target uses,
# and at all cores, kept in the record as all_threads_* (MESHEDIT_THREADS, threads.h).
ONE_THREAD, ALL_THREADS = "1", "0"

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

def size_label(size):
    """A size in a job name as the report writes it: 10k stays, 1m becomes 1M."""
    return size[:-1] + "M" if size.endswith("m") else size


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



# Programs whose every row is MeshEdit's (or, for bench_bandwidth, the machine's bound at
# both thread counts), and bench_python's MeshEdit impls; elsewhere the impl says (meshedit,
# meshedit_*). "all" is one process measuring several rows (draw, pick).
MESHEDIT_PROGRAMS = ("bench_bandwidth", "bench_build", "bench_local_ops", "bench_editor",
                     "bench_compare")
MESHEDIT_PYTHON_IMPLS = ("meshedit", "view", "copy", "python_calls", "one_apply")


def has_meshedit_rows(program, impl):
    """Whether the configuration measures MeshEdit, so that it runs at 1 and at all threads."""
    return (is_meshedit(impl) or impl == "all" or program in MESHEDIT_PROGRAMS
            or (program == "bench_python" and impl in MESHEDIT_PYTHON_IMPLS))


# How each anchor runs, stated beside its row and in the report's threading section: the
# anchors refine, decimate and load on one thread, so MeshEdit's 1-thread figure is the one
# that compares algorithms.
ANCHOR_THREADING = {
    "openmesh": "1 (OpenMesh has no parallel code)",
    "cgal": "1 (no `Parallel_tag`, no TBB)",
    "opensubdiv_min": "1 (Far refines on one thread)",
    "opensubdiv_full": "1 (Far refines on one thread)",
    "assimp": "1 (Assimp's importers)",
    "meshoptimizer": "1 (meshoptimizer has no threads)",
    "numpy_copy": "1 (numpy copies)",
    "numpy": "1 (numpy)",
    "open3d": "Open3D's own",
    "bare": "llvmpipe's (`LP_NUM_THREADS`, all cores)",
    "bare_culled": "llvmpipe's (`LP_NUM_THREADS`, all cores)",
    "id_pass": "llvmpipe's (`LP_NUM_THREADS`, all cores)",
}


def threading_of(record):
    """The threads column of a row: "1 / N" for a MeshEdit row measured both ways, else how the
    implementation runs."""
    if "all_threads_median_ms" in record:
        n = record.get("all_threads")
        return f"1 / {n:.0f}" if n else "1 / all"
    return ANCHOR_THREADING.get(record["impl"], "1")


def merge_thread_runs(one, every):
    """Adds each all-threads record of `every` to its 1-thread twin in `one` (same job and impl)
    as all_threads_min_ms, all_threads_median_ms, all_threads_runs and all_threads (MeshEdit's
    thread count in that process). A twin that is missing keeps the record on its own, named
    IMPL@all threads. Returns the records to report."""
    twins = {(r["job"], r["impl"]): r for r in one if "median_ms" in r}
    out = list(one)
    for r in every:
        if "median_ms" not in r:
            continue
        twin = twins.get((r["job"], r["impl"]))
        if twin is None:
            out.append(dict(r, impl=r["impl"] + "@all threads"))
            continue
        twin["all_threads_min_ms"] = r["min_ms"]
        twin["all_threads_median_ms"] = r["median_ms"]
        twin["all_threads_runs"] = r["runs"]
        if "meshedit_threads" in r:
            twin["all_threads"] = r["meshedit_threads"]
    return out
