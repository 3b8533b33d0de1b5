# Mesh.from_arrays(), V, faces(): numpy in and out, every bad input refused naming the argument.
import numpy as np
import pytest

import meshedit

SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)


def test_triangles_quads_and_polygons():
    tris = meshedit.Mesh.from_arrays(SQUARE, np.array([[0, 1, 2], [0, 2, 3]]))
    assert tris.info()["faces"] == 2 and tris.info()["boundary_loops"] == 1
    assert np.array_equal(tris.faces(), [[0, 1, 2], [0, 2, 3]])
    quad = meshedit.Mesh.from_arrays(SQUARE, [[0, 1, 2, 3]])
    assert quad.faces().shape == (1, 4)
    V = np.vstack([SQUARE, [[2, 0, 0], [2, 1, 0], [2.5, 0.5, 0]]])
    poly = meshedit.Mesh.from_arrays(V, [0, 4, 9], [0, 1, 2, 3, 1, 4, 6, 5, 2])
    assert poly.faces() == [[0, 1, 2, 3], [1, 4, 6, 5, 2]]
    assert poly.notices == []
    assert poly.validate() is None


def test_v_is_a_view_without_a_copy():
    mesh = meshedit.Mesh.from_arrays(SQUARE, [[0, 1, 2], [0, 2, 3]])
    V = mesh.V
    assert V.dtype == np.float64 and V.shape == (4, 3)
    assert np.shares_memory(V, mesh.V)
    V[2, 2] = 5.0
    assert mesh.info()["bbox"]["max"][2] == 5.0
    del mesh
    assert V[2, 2] == 5.0  # the view keeps the mesh alive


def test_dtypes_are_converted_or_refused():
    mesh = meshedit.Mesh.from_arrays(SQUARE.astype(np.float32), np.array([[0, 1, 2]], np.uint8))
    assert mesh.info()["faces"] == 1
    mesh = meshedit.Mesh.from_arrays(SQUARE.astype(int).tolist(), [[0, 1, 2]])
    assert mesh.V.dtype == np.float64
    with pytest.raises(TypeError, match="F: expected integers, got dtype float64"):
        meshedit.Mesh.from_arrays(SQUARE, np.array([[0.0, 1.0, 2.0]]))
    with pytest.raises(TypeError, match="V: expected numbers"):
        meshedit.Mesh.from_arrays([["a", "b", "c"]], [[0, 0, 0]])
    with pytest.raises(TypeError, match="F: expected integers"):
        meshedit.Mesh.from_arrays(SQUARE, "not faces")


def test_non_contiguous_arrays_are_copied():
    big = np.zeros((4, 6))
    big[:, ::2] = SQUARE
    faces = np.asfortranarray(np.array([[0, 1, 2], [0, 2, 3]]))
    mesh = meshedit.Mesh.from_arrays(big[:, ::2], faces)
    assert np.array_equal(mesh.V, SQUARE)


def test_bad_shapes_nans_and_indices_name_the_argument():
    with pytest.raises(ValueError, match=r"V: expected shape \(n, 3\), got \(4, 2\)"):
        meshedit.Mesh.from_arrays(SQUARE[:, :2], [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"F: expected shape \(n, 3\) or \(n, 4\), got \(1, 5\)"):
        meshedit.Mesh.from_arrays(SQUARE, [[0, 1, 2, 3, 0]])
    bad = SQUARE.copy()
    bad[1, 1] = np.nan
    with pytest.raises(ValueError, match="V: row 1 is not finite"):
        meshedit.Mesh.from_arrays(bad, [[0, 1, 2]])
    with pytest.raises(IndexError, match=r"F\[1, 2\] = 9 is out of range \(V has 4 rows\)"):
        meshedit.Mesh.from_arrays(SQUARE, [[0, 1, 2], [0, 2, 9]])
    with pytest.raises(IndexError, match=r"F\[0, 0\] = -1"):
        meshedit.Mesh.from_arrays(SQUARE, [[-1, 1, 2]])
    with pytest.raises(IndexError, match=r"indices\[2\] = 7"):
        meshedit.Mesh.from_arrays(SQUARE, [0, 3], [0, 1, 7])
    with pytest.raises(ValueError, match="offsets: must start at 0 and end at len"):
        meshedit.Mesh.from_arrays(SQUARE, [0, 4], [0, 1, 2])
    with pytest.raises(ValueError, match=r"offsets\[2\] = 2 is below"):
        meshedit.Mesh.from_arrays(SQUARE, [0, 3, 2, 3], [0, 1, 2])


def test_repairs_are_notices():
    # two triangles sharing a corner only: the bowtie vertex is split
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]], float)
    mesh = meshedit.Mesh.from_arrays(V, [[0, 1, 2], [0, 3, 4]])
    assert mesh.validate() is None
    assert any("split" in line for line in mesh.notices)


def test_edges_and_empty_mesh():
    mesh = meshedit.Mesh.from_arrays(SQUARE, [[0, 1, 2], [0, 2, 3]])
    assert mesh.edges().shape == (5, 2)
    empty = meshedit.Mesh()
    assert empty.V.shape == (0, 3) and empty.info()["vertices"] == 0
    assert meshedit.Mesh.from_arrays(np.zeros((0, 3)), np.zeros((0, 3), int)).info()["faces"] == 0
    assert meshedit.Mesh.from_arrays(SQUARE, [0], []).info()["vertices"] == 4
    with pytest.raises(meshedit.Refused, match="loop refused: cannot subdivide: the mesh has no faces"):
        empty.loop()


def test_a_view_kept_across_edits_stays_readable():
    import gc
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    mesh = meshedit.Mesh.from_arrays(V, [[0, 1, 2], [0, 2, 3]])
    old = mesh.V
    for _ in range(6):  # grows the position array past its first allocation
        mesh.loop()
    gc.collect()
    assert np.array_equal(old, V)  # the positions as they were, not freed memory
    old[0, 0] = 7.0  # writes into the detached copy, not the mesh
    assert mesh.V[0, 0] != 7.0
    assert mesh.V.shape[0] == mesh.info()["vertices"]
    doc = meshedit.Document(mesh)
    view = mesh.V
    doc.compact()
    doc.undo()
    doc.redo()
    assert view.shape[1] == 3 and np.isfinite(view).all()


def test_normals_and_creases(sample):
    mesh = meshedit.read(sample("cube.dae"))
    normals = mesh.vertex_normals()
    assert normals.shape == (8, 3)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1)
    assert ((normals * mesh.V).sum(axis=1) > 0.5).all()  # outward: the cube is centred on 0
    faces = mesh.face_normals()
    assert faces.shape == (12, 3) and np.allclose(np.abs(faces).sum(axis=1), 1)
    assert mesh.creases().shape == (0, 2)
    mesh.crease(0, 6)
    assert sorted(mesh.creases()[0]) == [0, 6]
    assert meshedit.read(sample("creased.dae")).creases().shape[0] > 0
