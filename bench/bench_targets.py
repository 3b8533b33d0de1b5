"""The targets table and the local-operations table of docs/performance.md, computed from the
records of one run (run_bench.py). Every ratio uses MeshEdit's 1-thread median: the anchors
run on one thread (issue 38), so the targets compare algorithms, not cores."""

import re

from bench_bound import normals_target_rows
from bench_results import (BUILD_SIZES, LOCAL_OPS, LOCAL_OPS_SIZES, QEM_JOBS, fmt_num,
                           is_meshedit, ok_results, ratio_info, size_label)


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


def carry_target_rows(jobs):
    """Issue 32: carrying texture coordinates and colours costs at most 1.5× the
    attribute-free time of the same operation on the same mesh (MeshEdit against itself)."""
    rows = []
    for label, plain, carried in (
            ("QEM 1M → 100k carrying UVs and colours", "qem_torus_1m_to_100k",
             "qem_torus_attrs_1m_to_100k"),
            ("Loop 1 level of 1M carrying UVs and colours", "loop_1m_1level",
             "loop_1m_attrs_1level"),
            ("Catmull-Clark 1 level of 1M carrying UVs and colours", "cc_1m_1level",
             "cc_1m_attrs_1level")):
        for suffix in ("", "_warm"):
            if plain + suffix not in jobs and carried + suffix not in jobs:
                continue
            a = ok_results(jobs.get(plain + suffix, [])).get("meshedit", {})
            b = ok_results(jobs.get(carried + suffix, [])).get("meshedit", {})
            name = label + (" (warm)" if suffix else "")
            if a.get("median_ms", 0) <= 0 or "median_ms" not in b:
                rows.append((name, "≤ 1.5 × without", "not measured", "n/a"))
                continue
            r = b["median_ms"] / a["median_ms"]
            rows.append((name, "≤ 1.5 × without",
                         f"{r:.2f}× ({b['median_ms']:.0f} vs {a['median_ms']:.0f} ms)",
                         "yes" if r <= 1.5 else "no"))
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
    rows = [(label, target, measured, "yes" if all(checks) else "no")]
    # Issue 38: the share of inner vertices of valence 6 at least CGAL's, on each input.
    for job, what in (("remesh_armadillo_208k", "208k-face armadillo"),
                      ("remesh_bunny_75k", "75k-face bunny scan"),
                      ("remesh_torus_80k", "80k-face torus")):
        res = ok_results(jobs.get(job, []))
        me, cgal = res.get("meshedit"), res.get("cgal")
        label = f"isotropic remeshing, valence-6 share of inner vertices, {what}"
        target = "≥ CGAL's (same input and target length)"
        if me is None or cgal is None or "valence6_pct" not in me:
            rows.append((label, target, f"not measured ({job})", "n/a"))
            continue
        rows.append((label, target,
                     f"{me['valence6_pct']:.1f}% vs {cgal.get('valence6_pct', 0):.1f}%; valence "
                     f"≤ 4: {me.get('valence4_or_less', 0):.0f} vs "
                     f"{cgal.get('valence4_or_less', 0):.0f}; Hausdorff "
                     f"{me.get('hausdorff_pct', 0):.4f}% vs {cgal.get('hausdorff_pct', 0):.4f}%",
                     "yes" if me["valence6_pct"] >= cgal.get("valence6_pct", 101) else "no"))
    return rows


def smooth_target_rows(jobs):
    """Issue 35: Laplacian smoothing ≤ 1/3 of the fastest anchor's time per iteration on 1M
    faces (OpenMesh's JacobiLaplaceSmootherT, CGAL's tangential_relaxation); implicit
    smoothing's solve time reported beside CGAL's smooth_shape."""
    rows = jobs.get("smooth_1m_uniform", [])
    me, ratios, fastest, r = ratio_info(rows)
    label = "Laplacian smoothing, 10 uniform iterations, 1M faces"
    target = "≤ 1/3 of the fastest anchor's time per iteration"
    if r is None:
        return [(label, target, "not measured (smooth_1m_uniform)", "n/a")]
    res = ok_results(rows)
    measured = (f"{r:.3f} of {fastest} ({me['median_ms'] / 10:.1f} vs "
                f"{res[fastest]['median_ms'] / 10:.1f} ms per iteration)")
    others = [f"{ratios[a]:.3f} of {a}" for a in sorted(ratios) if a != fastest
              and not is_meshedit(a)]
    if others:
        measured += "; " + ", ".join(others)
    implicit = ok_results(jobs.get("smooth_1m_implicit", []))
    if "meshedit" in implicit:
        measured += (f"; implicit step {implicit['meshedit']['median_ms']:.0f} ms (solve "
                     f"{implicit['meshedit'].get('solve_ms', 0):.0f} ms)")
        if "cgal" in implicit:
            measured += f" vs CGAL's smooth_shape {implicit['cgal']['median_ms']:.0f} ms"
    return [(label, target, measured, "yes" if r <= 1 / 3 else "no")]


def fill_jobs(jobs):
    """The hole-filling jobs (bench_fill), by scan and then hole size."""
    found = []
    for job in jobs:
        m = re.fullmatch(r"fill_(.+)_(\d+)", job)
        if m:
            found.append((m.group(1), int(m.group(2)), job))
    return sorted(found)


def fill_target_rows(jobs):
    """Issue 35's hole filling against CGAL's triangulate_refine_and_fair_hole, per hole: time
    ≤ 1/3 of CGAL's, Hausdorff distance to the surface cut away ≤ CGAL's, smallest angle of
    the patch ≥ CGAL's; the met column names each."""
    rows = []
    target = "time ≤ 1/3 of CGAL's; Hausdorff ≤ CGAL's; min angle ≥ CGAL's"
    for scan, size, job in fill_jobs(jobs):
        res = ok_results(jobs.get(job, []))
        me, cgal = res.get("meshedit"), res.get("cgal")
        label = f"hole filling, {scan.replace('_', ' ')}, hole of ≥ {size} edges"
        if me is None or cgal is None or not cgal["median_ms"] > 0:
            rows.append((label, target, f"not measured ({job})", "n/a"))
            continue
        r = me["median_ms"] / cgal["median_ms"]
        h_me, h_cgal = me.get("hausdorff_pct", 1e9), cgal.get("hausdorff_pct", 0)
        a_me, a_cgal = me.get("min_angle_deg", 0), cgal.get("min_angle_deg", 180)
        checks = (("time", r <= 1 / 3), ("Hausdorff", h_me <= h_cgal), ("angle", a_me >= a_cgal))
        measured = (f"{me.get('hole_edges', size):.0f} edges: {r:.3f} of CGAL "
                    f"({me['median_ms']:.1f} vs {cgal['median_ms']:.1f} ms); Hausdorff "
                    f"{h_me:.3g}% vs {h_cgal:.3g}%; min angle {a_me:.2f}° vs {a_cgal:.2f}°")
        met = ", ".join(f"{name} {'yes' if ok else 'no'}" for name, ok in checks)
        rows.append((label, target, measured, met))
    return rows


def selection_target_rows(jobs, not_measured):
    """Issue 37: region selection on a million faces (bench_selection)."""
    rows = []
    for job, label, limit in (("select_loop_1m", "edge loop, 1M quads (1000 edges)", 1.0),
                              ("select_ring_1m", "edge ring, 1M quads (1000 edges)", 1.0),
                              ("select_linked_1m", "select linked, 1M triangles", 50.0),
                              ("select_box_1m", "box select through, 1M triangles", 16.0),
                              ("select_box_visible_1m",
                               "box select of what shows, 1M triangles (the release; the "
                               "view's points kept from the press)", 16.0),
                              ("select_lasso_visible_1m",
                               "lasso select of what shows, 1M triangles (the release)", 16.0)):
        x = ok_results(jobs.get(job, [])).get("meshedit", {})
        if "p99_ms" not in x:
            rows.append((label, f"p99 ≤ {limit:g} ms", not_measured(job, "not run"), "n/a"))
            continue
        measured = f"p99 {x['p99_ms']:.3f} ms, p50 {x['median_ms']:.3f} ms"
        if "view_build_ms" in x:
            measured += f"; the press builds the view's points in {x['view_build_ms']:.1f} ms"
        rows.append((label, f"p99 ≤ {limit:g} ms", measured,
                     "yes" if x["p99_ms"] <= limit else "no"))
    cold = ok_results(jobs.get("select_box_visible_1m_cold", [])).get("meshedit", {})
    if "p99_ms" in cold:
        rows.append(("box select of what shows, 1M triangles, first region in a new view "
                     "(build and query)", "reported", f"p99 {cold['p99_ms']:.3f} ms, "
                     f"p50 {cold['median_ms']:.3f} ms", "n/a"))
    return rows


def editor_target_rows(jobs, not_measured):
    """Issue 20: the viewer's command layer and renderer at a million faces (bench_editor)."""
    rows = []
    for job, mesh in (("editor_edits_torus_1m", "1M torus"), ("editor_edits_scan_1m",
                                                                "1.2M scan"),
                      ("editor_edits_torus_10m", "10M torus")):
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
                 5.0),
                ("flip_with_diagram", "F with its rewiring diagram (panel shown)", 5.0)):
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
        x = r.get("extrude_move_upload", {})
        if "topology_changes" in x:
            rows.append((f"extrude drag builds its topology once, {mesh}",
                         "1 topology change, the rest position amendments",
                         f"{x['topology_changes']:.0f} topology change, "
                         f"{x.get('position_amendments', 0):.0f} amendments",
                         "yes" if x["topology_changes"] == 1 else "no"))
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
    simp = ok_results(jobs.get("editor_simplify_1m", []))
    if "core" in simp and "viewer" in simp:
        core = simp["core"]["median_ms"]
        v = simp["viewer"]["median_ms"]
        rows.append(("D in the viewer (in the background), 1.2M-face scan to half",
                     "≤ 1.2 × core simplify", f"{v:.0f} ms vs core {core:.0f} ms = {v / core:.2f}×",
                     "yes" if v <= 1.2 * core else "no"))
    else:
        rows.append(("D in the viewer (in the background), 1.2M-face scan to half",
                     "≤ 1.2 × core simplify",
                     not_measured("editor_simplify_1m", "core or viewer missing"), "n/a"))
    return rows


def pick_row(jobs, job, size, not_measured):
    """The BVH pick's p99 on the torus of `size` triangles (bench_io_draw's pick jobs)."""
    label = f"pick under the cursor, {size} triangles at 1280×800"
    picks = ok_results(jobs.get(job, []))
    if "bvh" not in picks or "p99_ms" not in picks["bvh"]:
        return (label, "p99 ≤ 5 ms", not_measured(job, "bvh missing"), "n/a")
    b = picks["bvh"]
    gpu = picks.get("id_pass", {})
    ref = (f"; ID pass p50 {gpu['p50_ms']:.0f} / p99 {gpu['p99_ms']:.0f} ms"
           if "p99_ms" in gpu else "")
    # The viewer builds the BVH for a whole-mesh change; a local edit updates it in place.
    return (label, "p99 ≤ 5 ms",
            f"p99 {b['p99_ms']:.3f} ms, p50 {b['p50_ms']:.3f} ms (BVH built in "
            f"{b.get('build_ms', 0):,.0f} ms){ref}", "yes" if b["p99_ms"] <= 5 else "no")


def ten_million_rows(jobs, not_measured):
    """Issue 38: a 10M-triangle torus (torus(2500, 2000)) loaded, opened, picked, refined."""
    rows = []
    me, ratios, fastest, ratio = ratio_info(jobs.get("loop_10m_1level", []))
    if me is not None and "bytes_per_face_exact" in me:
        b = me["bytes_per_face_exact"]
        vs = f"; {ratio:.3f} of {fastest}" if fastest else ""
        rows.append(("Loop, 1 level, 10M → 40M faces", "within memory, ≤ 70 bytes per face",
                     f"{b:.1f} bytes per face, peak RSS {me.get('peak_rss_mb', 0):,.0f} MB, "
                     f"{me['median_ms']:,.0f} ms{vs}", "yes" if b <= 70 else "no"))
    else:
        rows.append(("Loop, 1 level, 10M → 40M faces", "within memory, ≤ 70 bytes per face",
                     not_measured("loop_10m_1level", "meshedit missing"), "n/a"))
    load = ok_results(jobs.get("ply_load_10m_binary", []))
    if "meshedit" in load and "assimp" in load:
        m, a = load["meshedit"], load["assimp"]
        speedup = a["median_ms"] / m["median_ms"]
        rows.append(("binary PLY load, 10M triangles", "≥ 4 × faster than Assimp",
                     f"{speedup:.2f}× faster ({m['median_ms']:,.0f} vs {a['median_ms']:,.0f} "
                     f"ms); peak RSS {m.get('peak_rss_bytes_per_face', 0):.0f} bytes a face",
                     "yes" if speedup >= 4 else "no"))
        first = ok_results(jobs.get("first_frame_10m", [])).get("meshedit")
        label = "open a 10M-triangle file: read, upload, first frame (headless)"
        target = "≤ 1.5 × the fastest anchor's plain load of the file"
        if first:
            r = first["median_ms"] / a["median_ms"]
            rows.append((label, target, f"{r:.2f} × Assimp's load ({first['median_ms']:,.0f} vs "
                         f"{a['median_ms']:,.0f} ms)", "yes" if r <= 1.5 else "no"))
        else:
            rows.append((label, target, not_measured("first_frame_10m", "not run"), "n/a"))
    else:
        rows.append(("binary PLY load, 10M triangles", "≥ 4 × faster than Assimp",
                     not_measured("ply_load_10m_binary", "MeshEdit or Assimp missing"), "n/a"))
    rows.append(pick_row(jobs, "pick_10m", "10M", not_measured))
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
    rows += carry_target_rows(jobs)
    rows += remesh_target_rows(jobs)
    rows += smooth_target_rows(jobs)
    rows += fill_target_rows(jobs)
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
    # Normals: against the memory bandwidth (issue 38), no longer against OpenMesh.
    rows += normals_target_rows(jobs)
    # COLLADA and PLY.
    for job, label in (("collada_load_1m_triangles", "COLLADA load, 1M triangles"),
                       ("collada_load_1m_polylist",
                        "COLLADA load, 1M triangles, `<polylist>` + per-face normals (variant)"),
                       ("ply_load_1m_binary", "binary PLY load, 1M triangles"),
                       ("stl_load_1m_binary", "binary STL load, 1M triangles (welded)")):
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
    rows.append(pick_row(jobs, "pick_1m", "1M", not_measured))

    rows += editor_target_rows(jobs, not_measured)
    rows += ten_million_rows(jobs, not_measured)
    rows += selection_target_rows(jobs, not_measured)

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

    lines = ["| job | target | measured (1-thread median, MeshEdit / anchor) | met? |",
             "|---|---|---|---|"]
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

