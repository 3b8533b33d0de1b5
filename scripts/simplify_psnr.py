#!/usr/bin/env python3
"""PSNR of attribute-aware against attribute-blind QEM (issue 32 item 5, docs/simplify.md).

    scripts/simplify_psnr.py --meshedit build/src/cli/meshedit [--out DIR] [--size 256]
        [--renderer meshedit|own] [--color auto|texture|checker|vertex] [MODEL ...]

The table of docs/simplify.md: the defaults with --color auto and with --color checker on
duck.dae, sphere.dae, teapot_instancenodes.DAE, ClearCoatTest.gltf and spider.obj.

For each model: `meshedit convert MODEL orig.obj --ops triangulate`, then the same with
`simplify:R:attributes=A` for R in 0.1 and 0.02 and A in aware and blind; renders every
file from 8 fixed views (azimuths 0, 45, ..., 315 degrees, elevations +20 and -20 in turn)
with one camera per model (the original's bounding box: its centre, 2.2 diagonals away), and
prints a markdown table of the PSNR of each simplified model's renders against the
original's (the mean squared error over all pixels of the 8 views, 8-bit RGB).

Renderers: `meshedit` draws with `meshedit render --color C --camera AZ,EL,DIST` (the
viewer's shading; --color as that command takes it); `own` draws with the small z-buffer
rasterizer below (numpy, Pillow): unlit-ish albedo (0.6 + 0.4 |n.l| with face normals) of
the base-colour texture (`texture`, nearest texel), a UV checker of 16 x 16 squares
(`checker`) or the vertex colours (`vertex`); `auto` takes the first of these the model has.
The own renderer frames every file with the original's camera, so nothing but the
simplification differs between two images; `meshedit render` frames each file's own
bounding box (its centre moves by the simplification's drift).
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

VIEWS = [(az, 20 if i % 2 == 0 else -20) for i, az in enumerate(range(0, 360, 45))]
RATIOS = (0.1, 0.02)
MODES = ("aware", "blind")
DEFAULT_MODELS = [
    "/usr/share/assimp/models/Collada/duck.dae",
    "/usr/share/assimp/models/Collada/sphere.dae",
    "/usr/share/assimp/models/Collada/teapot_instancenodes.DAE",
    "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf",
    "/usr/share/assimp/models/OBJ/spider.obj",
]


def read_obj(path):
    """Positions, colours (or None), UVs, triangles as (v, vt) index triples and materials."""
    pos, col, uv, tris, tri_uv, tri_mat = [], [], [], [], [], []
    materials, current = {}, None
    folder = path.parent
    for line in path.read_text(errors="replace").splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            pos.append([float(x) for x in parts[1:4]])
            if len(parts) >= 7:
                col.append([float(x) for x in parts[4:7]])
        elif parts[0] == "vt":
            uv.append([float(parts[1]), float(parts[2])])
        elif parts[0] == "usemtl":
            current = parts[1]
        elif parts[0] == "mtllib":
            materials.update(read_mtl(folder / " ".join(parts[1:])))
        elif parts[0] == "f":
            corners = [c.split("/") for c in parts[1:]]
            vs = [int(c[0]) - 1 for c in corners]
            ts = [int(c[1]) - 1 if len(c) > 1 and c[1] else -1 for c in corners]
            for k in range(1, len(vs) - 1):
                tris.append([vs[0], vs[k], vs[k + 1]])
                tri_uv.append([ts[0], ts[k], ts[k + 1]])
                tri_mat.append(current)
    return {
        "pos": np.array(pos, float),
        "col": np.array(col, float) if len(col) == len(pos) and col else None,
        "uv": np.array(uv, float) if uv else None,
        "tris": np.array(tris, int),
        "tri_uv": np.array(tri_uv, int),
        "tri_mat": tri_mat,
        "materials": materials,
    }


def read_mtl(path):
    out, name = {}, None
    if not path.exists():
        return out
    for line in path.read_text(errors="replace").splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "newmtl":
            name = " ".join(parts[1:])
            out[name] = {"kd": (0.8, 0.8, 0.8), "map": None}
        elif parts[0] == "Kd" and name:
            out[name]["kd"] = tuple(float(x) for x in parts[1:4])
        elif parts[0] == "map_Kd" and name:
            out[name]["map"] = " ".join(parts[1:])
    return out


_TEXTURES = {}


def texture(ref, search):
    """The texture image `ref` names, as a float array, looked for beside the OBJ and the
    model; None when it cannot be read."""
    if ref is None:
        return None
    for folder in search:
        p = (folder / ref).resolve()
        if p.exists():
            if p not in _TEXTURES:
                try:
                    _TEXTURES[p] = np.asarray(Image.open(p).convert("RGB"), float) / 255.0
                except OSError:
                    _TEXTURES[p] = None
            return _TEXTURES[p]
    return None


def camera(mesh):
    lo, hi = mesh["pos"].min(0), mesh["pos"].max(0)
    return (lo + hi) / 2, float(np.linalg.norm(hi - lo))


def render(mesh, cam, view, size, color, search):
    """A size x size RGB image (float 0-1) of `mesh` from `view`, supersampled 2x."""
    centre, diag = cam
    az, el = (math.radians(a) for a in view)
    eye_dir = np.array([math.cos(el) * math.sin(az), math.sin(el), math.cos(el) * math.cos(az)])
    forward = -eye_dir
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    eye = centre + eye_dir * 2.2 * diag
    n = 2 * size
    focal = n / (2 * math.tan(math.radians(30) / 2))
    rel = mesh["pos"] - eye
    depth = rel @ forward
    sx = n / 2 + focal * (rel @ right) / depth
    sy = n / 2 - focal * (rel @ up) / depth
    zbuf = np.full((n, n), np.inf)
    img = np.ones((n, n, 3))  # white background
    light = eye_dir / np.linalg.norm(eye_dir)
    for t, tri in enumerate(mesh["tris"]):
        xs, ys, zs = sx[tri], sy[tri], depth[tri]
        x0, x1 = max(int(np.floor(xs.min())), 0), min(int(np.ceil(xs.max())), n - 1)
        y0, y1 = max(int(np.floor(ys.min())), 0), min(int(np.ceil(ys.max())), n - 1)
        if x0 > x1 or y0 > y1 or zs.min() <= 0:
            continue
        area = (xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0])
        if abs(area) < 1e-12:
            continue
        gx, gy = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        w0 = ((xs[1] - gx) * (ys[2] - gy) - (xs[2] - gx) * (ys[1] - gy)) / area
        w1 = ((xs[2] - gx) * (ys[0] - gy) - (xs[0] - gx) * (ys[2] - gy)) / area
        w2 = 1 - w0 - w1
        inside = (w0 >= 0) & (w1 >= 0) & (w2 >= 0)
        if not inside.any():
            continue
        z = 1 / (w0 / zs[0] + w1 / zs[1] + w2 / zs[2])  # perspective-correct weights below
        region = zbuf[y0:y1 + 1, x0:x1 + 1]
        hit = inside & (z < region)
        if not hit.any():
            continue
        region[hit] = z[hit]
        b = np.stack([w0 / zs[0], w1 / zs[1], w2 / zs[2]], -1)[hit] * z[hit][:, None]
        p = mesh["pos"][tri]
        normal = np.cross(p[1] - p[0], p[2] - p[0])
        normal /= max(np.linalg.norm(normal), 1e-30)
        shade = 0.6 + 0.4 * abs(float(normal @ light))
        img[y0:y1 + 1, x0:x1 + 1][hit] = shade * albedo(mesh, t, tri, b, color, search)
    return np.asarray(Image.fromarray((img * 255).round().astype(np.uint8)).resize(
        (size, size), Image.BOX), float)


def albedo(mesh, t, tri, b, color, search):
    mat = mesh["materials"].get(mesh["tri_mat"][t], {"kd": (0.8, 0.8, 0.8), "map": None})
    if color in ("texture", "checker") and mesh["uv"] is not None and mesh["tri_uv"][t].min() >= 0:
        uv = b @ mesh["uv"][mesh["tri_uv"][t]]
        tex = texture(mat["map"], search) if color == "texture" else None
        if tex is not None:
            h, w, _ = tex.shape
            i = np.clip(((1 - uv[:, 1]) % 1.0 * h).astype(int), 0, h - 1)
            j = np.clip((uv[:, 0] % 1.0 * w).astype(int), 0, w - 1)
            return tex[i, j]
        if color == "checker":
            odd = (np.floor(uv[:, 0] * 16) + np.floor(uv[:, 1] * 16)) % 2
            return np.where(odd[:, None] > 0, [0.9, 0.5, 0.2], [0.2, 0.4, 0.8])
    if color == "vertex" and mesh["col"] is not None:
        return b @ mesh["col"][tri]
    return np.tile(mat["kd"], (len(b), 1))


def auto_color(mesh, search):
    if mesh["uv"] is not None:
        maps = {m["map"] for m in mesh["materials"].values()}
        if any(texture(m, search) is not None for m in maps):
            return "texture"
        return "checker"
    return "vertex" if mesh["col"] is not None else "flat"


def psnr(images, reference):
    mse = np.mean([np.mean((a - b) ** 2) for a, b in zip(images, reference)])
    return float("inf") if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))}: {r.stderr.strip()}")
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("models", nargs="*", default=DEFAULT_MODELS)
    ap.add_argument("--meshedit", default="build/src/cli/meshedit")
    ap.add_argument("--out", default=None, help="where the OBJ files and renders go")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--renderer", choices=("own", "meshedit"), default="meshedit")
    ap.add_argument("--color", default="auto")
    args = ap.parse_args()
    out = Path(args.out or tempfile.mkdtemp(prefix="simplify_psnr_"))
    out.mkdir(parents=True, exist_ok=True)
    print("| model | faces | colour | R | faces aware / blind | PSNR aware (dB) | PSNR blind (dB) |")
    print("|---|---|---|---|---|---|---|")
    for model in args.models:
        model = Path(model)
        if not model.exists():
            print(f"skipped {model}: missing", file=sys.stderr)
            continue
        name = model.stem
        files = {"orig": out / f"{name}_orig.obj"}
        run([args.meshedit, "convert", model, files["orig"], "--ops", "triangulate"])
        for r in RATIOS:
            for mode in MODES:
                files[(r, mode)] = out / f"{name}_{r}_{mode}.obj"
                run([args.meshedit, "convert", model, files[(r, mode)], "--ops",
                     f"triangulate,simplify:{r}:attributes={mode}"])
        meshes = {k: read_obj(f) for k, f in files.items()}
        search = [out, model.parent]
        orig = meshes["orig"]
        color = auto_color(orig, search) if args.color == "auto" else args.color
        cam = camera(orig)

        def images(key):
            if args.renderer == "own":
                return [render(meshes[key], cam, v, args.size, color, search) for v in VIEWS]
            shots = []
            for i, (az, el) in enumerate(VIEWS):
                png = out / f"{files[key].stem}_{i}.png"
                run([args.meshedit, "render", files[key], "-o", png, "--size",
                     f"{args.size}x{args.size}", "--camera", f"{az},{el},{2.2 * cam[1]}",
                     "--color", color, "--no-features"])
                shots.append(np.asarray(Image.open(png).convert("RGB"), float))
            return shots

        reference = images("orig")
        for r in RATIOS:
            row = {mode: psnr(images((r, mode)), reference) for mode in MODES}
            faces = " / ".join(str(len(meshes[(r, m)]["tris"])) for m in MODES)
            print(f"| {model.name} | {len(orig['tris'])} | {color} | {r:g} | {faces} | "
                  f"{row['aware']:.2f} | {row['blind']:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
