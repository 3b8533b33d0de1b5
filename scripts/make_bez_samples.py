#!/usr/bin/env python3
"""Generates MeshEdit's procedural Bezier samples (the teaset comes from convert_teapot.py).

    python3 scripts/make_bez_samples.py bez/

writes
  wavy_cube.bez  six bicubic patches on the faces of the cube [-1.5, 1.5]^3. Every patch's
                 border control points lie on the cube's edges at -1.5, -0.5, 0.5, 1.5, so
                 neighbouring patches share their border curves exactly and the tessellation
                 welds into one closed surface; the four inner control points of each face are
                 pushed in and out along the face normal (a saddle-shaped wave). Each patch is
                 oriented so that (u, v) = (column, row) directions cross to the outward normal.
  curve1.bzc     4 control points: an S-curve.
  curve2.bzc     5 control points: a double arch.
  curve6.bzc     6 control points: a curl.
All coordinates are short decimals, so the files are exact and the output deterministic.
Only the Python standard library is used.
"""

import os
import sys

HALF = 1.5
WAVE = 0.6  # inner control point offset along the normal

# (normal, U, V) with U x V = normal: columns run along U, rows along V.
FACES = [
    ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
    ((0, 0, -1), (0, 1, 0), (1, 0, 0)),
]

CURVES = {
    "curve1.bzc": [(0.1, 0.2), (0.3, 0.9), (0.7, 0.1), (0.9, 0.8)],
    "curve2.bzc": [(0.05, 0.3), (0.25, 0.95), (0.5, 0.05), (0.75, 0.95), (0.95, 0.3)],
    "curve6.bzc": [(0.1, 0.1), (0.9, 0.15), (0.85, 0.9), (0.15, 0.9), (0.2, 0.35), (0.6, 0.5)],
}


def fmt(v):
    v = 0.0 if v == 0 else round(v, 10)  # no "-0", no 0.30000000000000004
    s = repr(v)
    return s[:-2] if s.endswith(".0") else s


def wavy_cube():
    steps = [-HALF, -HALF / 3, HALF / 3, HALF]
    patches = []
    for n, u, v in FACES:
        cp = []
        for row in range(4):
            for col in range(4):
                inner = row in (1, 2) and col in (1, 2)
                # A saddle: the diagonal inner points go out, the anti-diagonal ones go in.
                bump = (WAVE if row == col else -WAVE) if inner else 0.0
                cp.append(
                    tuple(
                        n[k] * (HALF + bump) + u[k] * steps[col] + v[k] * steps[row]
                        for k in range(3)
                    )
                )
        patches.append(cp)
    return patches


def main(argv):
    if len(argv) != 2:
        sys.exit(f"usage: {argv[0]} OUTPUT_DIR")
    out = argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "wavy_cube.bez"), "w", encoding="ascii", newline="\n") as f:
        f.write("# A wavy cube: 6 bicubic patches (scripts/make_bez_samples.py).\n")
        patches = wavy_cube()
        f.write(f"{len(patches)}\n")
        for k, cp in enumerate(patches):
            f.write(f"# patch {k}\n")
            for r in range(4):
                f.write("  ".join(" ".join(fmt(c) for c in p) for p in cp[4 * r : 4 * r + 4]))
                f.write("\n")
    for name, points in CURVES.items():
        with open(os.path.join(out, name), "w", encoding="ascii", newline="\n") as f:
            f.write(f"# A Bezier curve of degree {len(points) - 1} in the [0,1] view ")
            f.write("(scripts/make_bez_samples.py).\n")
            f.write(f"{len(points)}\n")
            for x, y in points:
                f.write(f"{fmt(x)} {fmt(y)}\n")


if __name__ == "__main__":
    main(sys.argv)
