#!/usr/bin/env python3
"""Converts the Newell teaset (teapot, teacup, teaspoon) to MeshEdit's .bez format.

Source
------
The bicubic Bezier patches come from freeglut's ``src/fg_teapot_data.h`` (freeglut 3.4.0 as
packaged by Debian 12). Get it with a ``deb-src`` entry and ``apt-get source``::

    echo 'deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] \\
          http://deb.debian.org/debian bookworm main' > /etc/apt/sources.list.d/debsrc.list
    apt-get update && cd /tmp && apt-get source freeglut

then re-run (from the repository root)::

    python3 scripts/convert_teapot.py /tmp/freeglut-3.4.0/src/fg_teapot_data.h bez/

Licence
-------
Martin Newell's teaset (1975; the teapot made famous by Jim Blinn) is a set of measured
figures that has circulated freely for decades and is generally treated as public domain; the
copy freeglut used was distributed by Philip Schneider in 1990 (the header quotes his message).
freeglut's arrays are that data scaled, deduplicated by symmetry, with a bottom added to the
teapot and the teaspoon's top gap closed; that file carries freeglut's MIT/X11 notice, which
this script copies into every generated file so the outputs stay compliant either way.

What the script does
--------------------
freeglut stores only the unique patches: for the teapot and the teacup the first six input
patches are repeated rotated by 0, 90, 180 and 270 degrees about the up axis, the others are
repeated mirrored (the mirror copy reverses the row order, which keeps the winding). It also
draws the data rotated to Y-up. The script does exactly what fg_teapot.c does to the control
points (up axis conversion (x, y, z) -> (x, z, -y), then the rotations and mirrors, in
freeglut's order) but keeps freeglut's data scale and does not translate, so the teapot
stands on y = 0. One edit: the teapot lid's top row is put back on its pole (see
LID_POLE_FIX). Patch counts: teapot 32, teacup 26, teaspoon 16.

Only the Python standard library is used. The output is deterministic.
"""

import os
import re
import sys

# (name, rotate-and-mirror like freeglut's rotFlip)
OBJECTS = [("teapot", True), ("teacup", True), ("teaspoon", False)]

FREEGLUT_NOTICE = """\
Derived from freeglut's src/fg_teapot_data.h, which carries this notice:
Permission is hereby granted, free of charge, to any person obtaining a
copy of this software and associated documentation files (the "Software"),
to deal in the Software without restriction, including without limitation
the rights to use, copy, modify, merge, publish, distribute, sublicense,
and/or sell copies of the Software, and to permit persons to whom the
Software is furnished to do so, subject to the following conditions:
The above copyright notice and this permission notice shall be included
in all copies or substantial portions of the Software.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS
OR IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT.  IN NO EVENT SHALL
PAWEL W. OLSZTA BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER
IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN
CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE."""


def array_body(text, name):
    """The text between the braces of `static ... name[...]... = { ... };`."""
    m = re.search(r"\b" + re.escape(name) + r"\s*\[[^=]*=\s*\{", text)
    if not m:
        sys.exit(f"convert_teapot: {name} not found")
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    # Comments inside the initialiser (/* rim */) would otherwise look like numbers.
    return re.sub(r"/\*.*?\*/", " ", text[m.end() : i - 1], flags=re.S)


def parse(text, name):
    patch_body = array_body(text, "patchdata_" + name)
    rows = re.findall(r"\{([^{}]*)\}", patch_body)
    patches = [[int(v) for v in re.findall(r"-?\d+", r)] for r in rows]
    cp_body = array_body(text, "cpdata_" + name)
    points = []
    for r in re.findall(r"\{([^{}]*)\}", cp_body):
        vals = [float(v) for v in re.findall(r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?", r)]
        if len(vals) != 3:
            sys.exit(f"convert_teapot: bad control point {{{r}}} in cpdata_{name}")
        points.append(vals)
    for p in patches:
        if len(p) != 16 or max(p) >= len(points):
            sys.exit(f"convert_teapot: bad patch {p} in patchdata_{name}")
    return patches, points


# freeglut moved two control points of the lid's top row 0.002 off the axis so that its own
# evaluator gets a usable normal there; that opens a pin-hole at the top of the knob. The
# original Newell data has the whole row at the pole (0, 0, 3.15), which MeshEdit's tessellator
# handles (triangles at a pole are dropped), so the pole is restored.
LID_POLE_FIX = {
    "teapot": {(0.0, -0.002, 3.15): (0.0, 0.0, 3.15), (0.002, 0.0, 3.15): (0.0, 0.0, 3.15)}
}


def expand(patches, points, rot_flip):
    """freeglut's fghTeaset + rotOrReflect, on control points instead of sampled vertices."""
    out = []
    for k, patch in enumerate(patches):
        # Y-up as fg_teapot.c draws it: (x, y, z) -> (x, z, -y).
        cp = [(points[i][0], points[i][2], -points[i][1]) for i in patch]
        out.append(cp)
        if not rot_flip:
            continue
        if k < 6:
            out.append([(z, y, -x) for (x, y, z) in cp])  # 90 degrees about y
            out.append([(-x, y, -z) for (x, y, z) in cp])  # 180
            out.append([(-z, y, x) for (x, y, z) in cp])  # 270
        else:
            # Mirror across z = 0; reversing the rows keeps the winding (freeglut's comment).
            rows = [cp[4 * r : 4 * r + 4] for r in range(4)]
            out.append([(x, y, -z) for row in reversed(rows) for (x, y, z) in row])
    return out


def fmt(v):
    v = 0.0 if v == 0 else v  # no "-0"
    s = repr(v)
    return s[:-2] if s.endswith(".0") else s


def write_bez(path, name, patches):
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write(f"# Newell's {name} as bicubic Bezier patches, Y-up (MeshEdit .bez).\n")
        f.write("# Generated by scripts/convert_teapot.py; do not edit by hand.\n#\n")
        for line in FREEGLUT_NOTICE.splitlines():
            f.write(f"# {line}\n")
        f.write(f"{len(patches)}\n")
        for k, cp in enumerate(patches):
            f.write(f"# patch {k}\n")
            for r in range(4):
                f.write("  ".join(" ".join(fmt(c) for c in p) for p in cp[4 * r : 4 * r + 4]))
                f.write("\n")


def main(argv):
    if len(argv) != 3:
        sys.exit(f"usage: {argv[0]} PATH/TO/fg_teapot_data.h OUTPUT_DIR")
    with open(argv[1], encoding="latin-1") as f:  # the header's comment is not UTF-8
        text = f.read()
    os.makedirs(argv[2], exist_ok=True)
    for name, rot_flip in OBJECTS:
        patches, points = parse(text, name)
        fixes = LID_POLE_FIX.get(name, {})
        points = [list(fixes.get(tuple(p), p)) for p in points]
        if fixes and sum(1 for p in points if tuple(p) in fixes.values()) < len(fixes) + 1:
            sys.exit(f"convert_teapot: the lid pole of {name} was not found")
        out = expand(patches, points, rot_flip)
        path = os.path.join(argv[2], name + ".bez")
        write_bez(path, name, out)
        print(f"{path}: {len(out)} patches")


if __name__ == "__main__":
    main(sys.argv)
