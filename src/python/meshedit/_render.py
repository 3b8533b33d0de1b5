"""meshedit.render(): the headless renderer (meshedit-render, OSMesa) as a numpy image.

The mesh goes to meshedit-render through a temporary file and the picture comes back as a PNG,
decoded here with zlib and numpy (no imaging library needed). Each call starts the program:
about a tenth of a second besides the drawing.
"""
import os
import pathlib
import shutil
import struct
import subprocess
import tempfile
import zlib

import numpy as np


def _renderer():
    """meshedit-render: $MESHEDIT_RENDER, the build tree's, the prefix's, else PATH."""
    here = pathlib.Path(__file__).resolve().parent
    candidates = [os.environ.get("MESHEDIT_RENDER"),
                  here.parents[1] / "src" / "headless" / "meshedit-render",  # <build>/python/meshedit
                  here.parents[3] / "bin" / "meshedit-render",  # <prefix>/lib/python3/dist-packages/meshedit
                  shutil.which("meshedit-render")]
    for candidate in candidates:
        if candidate and os.access(candidate, os.X_OK):
            return str(candidate)
    raise FileNotFoundError("meshedit.render: meshedit-render not found (build it, install it, "
                            "or set MESHEDIT_RENDER)")


def _unfilter(raw, height, stride, bpp):
    out = np.zeros((height, stride), dtype=np.uint8)
    prev = np.zeros(stride, dtype=np.uint8)
    pos = 0
    for y in range(height):
        kind = raw[pos]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=pos + 1)
        pos += stride + 1
        if kind == 0:
            row = line.copy()
        elif kind == 1:
            row = np.cumsum(line.reshape(-1, bpp), axis=0, dtype=np.uint8).reshape(-1)
        elif kind == 2:
            row = line + prev
        elif kind in (3, 4):
            row = bytearray(line.tobytes())
            up = prev.tobytes()
            for i in range(stride):
                left = row[i - bpp] if i >= bpp else 0
                if kind == 3:
                    row[i] = (row[i] + ((left + up[i]) >> 1)) & 0xFF
                else:
                    corner = up[i - bpp] if i >= bpp else 0
                    p = left + up[i] - corner
                    pa, pb, pc = abs(p - left), abs(p - up[i]), abs(p - corner)
                    pred = left if pa <= pb and pa <= pc else (up[i] if pb <= pc else corner)
                    row[i] = (row[i] + pred) & 0xFF
            row = np.frombuffer(bytes(row), dtype=np.uint8)
        else:
            raise ValueError(f"PNG: unknown filter {kind} on row {y}")
        out[y] = row
        prev = out[y]
    return out


def decode_png(data):
    """An 8-bit RGB or RGBA, non-interlaced PNG as an (H, W, 4) uint8 array."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("PNG: bad signature")
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat.append(chunk)
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(f"PNG: depth {depth}, colour type {colour}, interlace {interlace} "
                         "not supported")
    bpp = 4 if colour == 6 else 3
    pixels = _unfilter(zlib.decompress(b"".join(idat)), height, width * bpp, bpp)
    pixels = pixels.reshape(height, width, bpp)
    if bpp == 3:
        pixels = np.concatenate([pixels, np.full((height, width, 1), 255, np.uint8)], axis=2)
    return pixels


def render(mesh, width=512, height=384, shading="phong", **options):
    """The mesh drawn headless as an (height, width, 4) uint8 RGBA array.

    shading: a mode name or number of `meshedit render --shading` (phong, normals, grey,
    studio, matcap, depth, hemisphere, envmap). Other options are meshedit-render's, with
    underscores for dashes: flat=True, wireframe=True, camera="30,20", field="gauss",
    up="z", samples=1 … (`meshedit render --help`).
    """
    if int(width) < 1 or int(height) < 1:
        raise ValueError(f"render: width and height must be positive, got {width}x{height}")
    command = [_renderer(), "--size", f"{int(width)}x{int(height)}", "--shading", str(shading)]
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if value is True:
            command.append(flag)
        elif value is not False and value is not None:
            command += [flag, ",".join(map(str, value)) if isinstance(value, (tuple, list))
                        else str(value)]
    with tempfile.TemporaryDirectory(prefix="meshedit-render-") as folder:
        # PLY is the fastest to write; COLLADA when the mesh holds what PLY cannot (creases).
        source = os.path.join(folder, "mesh.ply")
        if mesh.write(source):
            source = os.path.join(folder, "mesh.dae")
            mesh.write(source)
        image = os.path.join(folder, "image.png")
        done = subprocess.run(command + ["-o", image, source], capture_output=True, text=True)
        if done.returncode != 0:
            message = done.stderr.strip().replace(source, "<mesh>") or f"exit status {done.returncode}"
            raise RuntimeError(f"render: {message}")
        with open(image, "rb") as file:
            return decode_png(file.read())
