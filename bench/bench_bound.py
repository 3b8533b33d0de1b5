"""The physical limit as an anchor (issue 38): the memory bandwidth bench_bandwidth measured
(STREAM-style copy and triad, at 1 thread and at all), each bandwidth-bound pass's compulsory
bytes (`bytes_moved`, printed by the bench programs) and the time those bytes take at that
bandwidth, with the arithmetic written out in docs/performance.md."""

from bench_results import fmt_ms, ok_results

# The passes whose MeshEdit row prints bytes_moved, in the report's order (warm twins follow).
BOUND_JOBS = ("normals_6p4m", "loop_1m_1level", "loop_100k_levels_1", "cc_1m_1level",
              "cc_100k_levels_1", "ply_load_1m_binary", "stl_load_1m_binary",
              "collada_load_1m_triangles",
              "collada_load_1m_polylist")
NORMALS_LIMIT = 1.5  # the target: area-weighted normals within 1.5× of the bound


def triad(jobs):
    """(GB/s at 1 thread, GB/s at all threads or None, the all-threads count) from the fastest
    triad repetition, or None when bench_bandwidth did not run."""
    r = ok_results(jobs.get("stream_triad", [])).get("machine")
    if r is None or "bytes" not in r:
        return None
    every = r.get("all_threads_min_ms")
    return (r["bytes"] / (r["min_ms"] * 1e6), r["bytes"] / (every * 1e6) if every else None,
            r.get("all_threads"))


def bound_ms(bytes_moved, gb_per_s):
    return bytes_moved / (gb_per_s * 1e6)


def arithmetic(bytes_moved, gb_per_s):
    return (f"{bytes_moved / 1e6:,.1f} MB ÷ {gb_per_s:.2f} GB/s = "
            f"{fmt_ms(bound_ms(bytes_moved, gb_per_s))} ms")


def bandwidth_section(jobs):
    """The report's bandwidth section: the kernels, then every pass against its bound."""
    kernels = [(name, ok_results(jobs.get(f"stream_{name}", [])).get("machine"))
               for name in ("copy", "triad")]
    if not any(r for _, r in kernels):
        return []
    lines = [
        "## Memory bandwidth: the physical limit (issue 38)",
        "",
        "`bench_bandwidth`: McCalpin's STREAM copy (`c = a`, 16 bytes an element) and triad "
        "(`a = b + s·c`, 24) over arrays of 2^24 doubles (128 MiB each, four times the L3), in "
        "huge pages, first touched untimed; GB/s from the fastest repetition (STREAM's "
        "convention; the median in brackets), write-allocate reads not counted.",
        "",
        "| kernel | bytes a pass | 1 thread GB/s | all threads GB/s |",
        "|---|---:|---:|---:|",
    ]
    for name, r in kernels:
        if r is None:
            lines.append(f"| {name} | – | not measured | – |")
            continue
        every = r.get("all_threads_min_ms")
        all_cell = (f"{r['bytes'] / (every * 1e6):.2f} "
                    f"({r['bytes'] / (r['all_threads_median_ms'] * 1e6):.2f}), "
                    f"{r.get('all_threads', '?'):.0f} threads" if every else "–")
        lines.append(f"| {name} | {r['bytes'] / 1e6:,.1f} MB | {r['gb_per_s']:.2f} "
                     f"({r['gb_per_s_median']:.2f}) | {all_cell} |")
    lines.append("")
    bw = triad(jobs)
    if bw is None:
        return lines
    one, every, _ = bw
    lines += [
        "A pass's **bytes moved** are its compulsory traffic: every array it reads, read once, "
        "every array it writes, written once (vertex normals: 5 bytes per face — its halfedge "
        "and deleted flag —, 8 per halfedge — next and to-vertex —, 48 per vertex — the "
        "position read, the normal written; one level of Loop or Catmull-Clark: `Mesh::bytes()` "
        "of the input plus that of the result; loading: the file plus the result's "
        "`Mesh::bytes()`). Its **bound** is that traffic at the triad bandwidth of the same "
        "thread count: no implementation moving those bytes beats it. **Fraction** is bound / "
        "median (1: at the limit); MeshEdit's medians, cold unless the job says `_warm` (a "
        "cold run also pays the kernel for zeroing fresh pages, which the bound does not "
        "count). A pass that moves less than a few times the L3 (the 100k-face rows) partly "
        "runs from cache, so its bound is loose there.",
        "",
        "| pass | bytes moved | 1 thread: bound | median | fraction | all threads: bound "
        "| median | fraction |",
        "|---|---:|---|---:|---:|---|---:|---:|",
    ]
    for job in [j for base in BOUND_JOBS for j in (base, base + "_warm")]:
        me = ok_results(jobs.get(job, [])).get("meshedit")
        if me is None or "bytes_moved" not in me:
            continue
        b = me["bytes_moved"]
        cells = [arithmetic(b, one), fmt_ms(me["median_ms"]),
                 f"{bound_ms(b, one) / me['median_ms']:.2f}"]
        m_all = me.get("all_threads_median_ms")
        if every and m_all:
            cells += [arithmetic(b, every), fmt_ms(m_all), f"{bound_ms(b, every) / m_all:.2f}"]
        else:
            cells += ["–", "–", "–"]
        lines.append(f"| `{job}` | {b / 1e6:,.1f} MB | " + " | ".join(cells) + " |")
    lines.append("")
    return lines


def normals_target_rows(jobs):
    """Area-weighted normals within 1.5× of the bandwidth bound, on one thread (it replaces
    "≤ 0.1 × OpenMesh", which can ask for less time than the bytes take)."""
    target = f"≤ {NORMALS_LIMIT:g} × the bandwidth bound, 1 thread"
    bw = triad(jobs)
    rows = []
    for job, label in (("normals_6p4m", "area-weighted normals, 6.4M faces"),
                       ("normals_6p4m_warm", "area-weighted normals, 6.4M faces (warm)")):
        res = ok_results(jobs.get(job, []))
        me = res.get("meshedit")
        if me is None or "bytes_moved" not in me or bw is None:
            if job == "normals_6p4m":
                why = "no stream_triad" if bw is None else "MeshEdit missing"
                rows.append((label, target, f"not measured ({why})", "n/a"))
            continue
        bound = bound_ms(me["bytes_moved"], bw[0])
        ratio = me["median_ms"] / bound
        measured = (f"{fmt_ms(me['median_ms'])} ms = {ratio:.2f} × the bound "
                    f"({arithmetic(me['bytes_moved'], bw[0])})")
        om = res.get("openmesh")
        if om:
            tenth = om["median_ms"] / 10
            measured += (f"; the old target, 0.1 × OpenMesh = {fmt_ms(tenth)} ms, is "
                         + ("below the bound: past the limit" if tenth < bound else
                            "above the bound"))
        rows.append((label, target, measured, "yes" if ratio <= NORMALS_LIMIT else "no"))
    return rows
