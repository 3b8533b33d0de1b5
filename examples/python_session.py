#!/usr/bin/env python3
"""A MeshEdit session from Python: read a mesh, look at it, edit it with undo, write it.

    PYTHONPATH=build/python python3 examples/python_session.py dae/cube.dae /tmp

Run by the test suite (tests/python/test_example.py).
"""
import pathlib
import sys

import numpy as np

import meshedit


def main(path, out_dir):
    mesh = meshedit.read(path)
    info = mesh.info()
    print(f"{path}: V={info['vertices']} E={info['edges']} F={info['faces']} "
          f"genus={info['genus']}")

    doc = meshedit.Document(mesh)
    doc.flip(0, 6)
    doc.split(0, 1)
    try:
        doc.collapse(0, 99)          # no such edge: a BadStep (a ValueError)
    except meshedit.BadStep as error:
        print("not run:", error)
    doc.loop()
    doc.undo()                       # back to the split mesh
    doc.redo()
    print("session:", ", ".join(doc.session))

    V = mesh.V                       # a view: scaling it scales the mesh
    V *= 2.0
    print("bbox:", mesh.info()["bbox"], "valence mean:", np.nanmean(mesh.field("valence")))

    out = pathlib.Path(out_dir) / (pathlib.Path(path).stem + "_edited.ply")
    unkept = mesh.write(out)
    print("wrote", out, "(lost: " + "; ".join(unkept) + ")" if unkept else "")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: python_session.py MESH OUT_DIR")
    main(sys.argv[1], sys.argv[2])
