#!/usr/bin/env python3
"""bench_python: the Python module's costs (issue 33, item 7), in bench/run_bench.py's protocol.

    bench_python --list
    bench_python --job JOB --impl IMPL [--runs N]   (MESHEDIT_THREADS sets the threads)

Jobs (a 1M-triangle torus made with numpy, 1000 × 500 quads cut in two):
  py_from_arrays_1m   meshedit: Mesh.from_arrays(V, F) (checks, then the halfedge build);
                      numpy_copy: V.copy() and F.copy(), the floor of any conversion; open3d:
                      TriangleMesh(Vector3dVector(V), Vector3iVector(F)) (no halfedges)
  py_positions_1m     view: mesh.V (no copy); copy: np.array(mesh.V)
  py_flip_1000        python_calls: 1000 × mesh.flip(a, b); one_apply: one mesh.apply() of the
                      same 1000 steps (parsed and run in C++); the difference over 1000 is the
                      per-call cost of Python (a flip itself is well under a microsecond)
  py_read_ply_1m      meshedit: meshedit.read() of the binary PLY; numpy: the same file read with
                      numpy alone (header parsed, the body as structured arrays: the floor of
                      any reader); open3d: o3d.io.read_triangle_mesh (Debian's python3-open3d,
                      when installed; trimesh and PyMeshLab are not packaged by Debian 12)
<build>/bench/bench_python (written by bench/CMakeLists.txt) runs this script with the
module's Python and PYTHONPATH=<build>/python.
"""
import argparse
import json
import os
import statistics
import sys
import tempfile
import time

import numpy as np  # noqa: E402

import meshedit  # noqa: E402

CONFIGS = [("py_from_arrays_1m", "meshedit"), ("py_from_arrays_1m", "numpy_copy"),
           ("py_from_arrays_1m", "open3d"),
           ("py_positions_1m", "view"), ("py_positions_1m", "copy"),
           ("py_flip_1000", "python_calls"), ("py_flip_1000", "one_apply"),
           ("py_read_ply_1m", "meshedit"), ("py_read_ply_1m", "numpy"),
           ("py_read_ply_1m", "open3d")]


def torus(n=1000, m=500, r1=1.0, r2=0.3):
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)[:, None]
    v = np.linspace(0, 2 * np.pi, m, endpoint=False)[None, :]
    V = np.stack([(r1 + r2 * np.cos(v)) * np.cos(u), (r1 + r2 * np.cos(v)) * np.sin(u),
                  np.broadcast_to(r2 * np.sin(v), (n, m))], axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    a = i * m + j
    b = ((i + 1) % n) * m + j
    c = ((i + 1) % n) * m + (j + 1) % m
    d = i * m + (j + 1) % m
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                        np.stack([a, c, d], -1).reshape(-1, 3)])
    return np.ascontiguousarray(V), F.astype(np.int64)


def read_ply_numpy(path):
    """A binary little-endian PLY of triangles with numpy alone."""
    with open(path, "rb") as file:
        header, elements = [], []
        while True:
            line = file.readline().decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
            words = line.split()
            if words[0] == "element":
                elements.append([words[1], int(words[2]), []])
            elif words[0] == "property":
                elements[-1][2].append(words[1:])
        types = {"double": "<f8", "float": "<f4", "uchar": "u1", "int": "<i4", "uint": "<u4"}
        arrays = {}
        for name, count, props in elements:
            if props[0][0] == "list":
                _, count_type, index_type, field = props[0]
                dtype = np.dtype([("n", types[count_type]), (field, types[index_type], 3)])
            else:
                dtype = np.dtype([(p[1], types[p[0]]) for p in props])
            arrays[name] = np.fromfile(file, dtype=dtype, count=count)
    vertex = arrays["vertex"]
    V = np.stack([vertex["x"], vertex["y"], vertex["z"]], axis=1)
    F = arrays["face"]["vertex_indices"]
    assert (arrays["face"]["n"] == 3).all()
    return V, F


# bench_util.h's rule for short jobs: a median under 20 ms repeats until 0.5 s of timed
# repetitions (at most 2000, and no more after 30 s of wall time), so min and median are stable.
SHORT_JOB_MS, STABLE_TOTAL_MS, MAX_RUNS, MAX_WALL_S = 20.0, 500.0, 2000, 30.0


def wants_more_runs(times, started):
    return (times and statistics.median(times) < SHORT_JOB_MS and sum(times) < STABLE_TOTAL_MS
            and len(times) < MAX_RUNS and time.monotonic() - started < MAX_WALL_S)


def timed(run, runs, setup=None):
    times = []
    started = time.monotonic()
    while len(times) < runs or wants_more_runs(times, started):
        state = setup() if setup else None
        start = time.perf_counter()
        run(state)
        times.append((time.perf_counter() - start) * 1000)
    return times


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--job")
    parser.add_argument("--impl")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--warm", action="store_true")
    args = parser.parse_args()
    if args.list:
        for job, impl in CONFIGS:
            print(job, impl)
        return 0
    if (args.job, args.impl) not in CONFIGS:
        print(f"bench_python: unknown job/impl {args.job} {args.impl}", file=sys.stderr)
        return 2
    extra = {}
    V, F = torus()
    if args.impl == "open3d":
        try:
            import open3d as o3d
        except ImportError:
            print("INFO open3d: python3-open3d is not installed (apt-get install "
                  "python3-open3d); trimesh and PyMeshLab are not packaged by Debian 12")
            return 1
    if args.job == "py_from_arrays_1m":
        if args.impl == "meshedit":
            times = timed(lambda _: meshedit.Mesh.from_arrays(V, F), args.runs)
        elif args.impl == "open3d":
            F32 = F.astype(np.int32)
            times = timed(lambda _: o3d.geometry.TriangleMesh(
                o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F32)), args.runs)
        else:
            times = timed(lambda _: (V.copy(), F.copy()), args.runs)
    elif args.job == "py_positions_1m":
        mesh = meshedit.Mesh.from_arrays(V, F)
        if args.impl == "view":
            times = timed(lambda _: mesh.V, args.runs)
        else:
            times = timed(lambda _: np.array(mesh.V), args.runs)
    elif args.job == "py_flip_1000":
        small_V, small_F = torus(250, 200)  # 100,000 triangles
        base = meshedit.Mesh.from_arrays(small_V, small_F)
        # the diagonals of 1000 quads spread over the torus: each one flips independently
        edges = [(int(a), int(c)) for a, _, c in small_F[:50000:50]]
        if args.impl == "python_calls":
            def run(mesh):
                for a, c in edges:
                    mesh.flip(a, c)
        else:
            text = ",".join(f"flip:{a}-{c}" for a, c in edges)

            def run(mesh):
                mesh.apply(text)
        times = timed(run, args.runs, setup=base.copy)
        extra["flips"] = len(edges)
    else:
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "torus.ply")
            meshedit.Mesh.from_arrays(V, F).write(path, normals=False)
            if args.impl == "meshedit":
                times = timed(lambda _: meshedit.read(path), args.runs)
            elif args.impl == "numpy":
                times = timed(lambda _: read_ply_numpy(path), args.runs)
            else:
                times = timed(lambda _: o3d.io.read_triangle_mesh(path), args.runs)
    result = {"job": args.job, "impl": args.impl, "runs": len(times), "min_ms": min(times),
              "median_ms": statistics.median(times), "meshedit_threads": meshedit.threads(),
              **extra}
    print("RESULT " + json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
