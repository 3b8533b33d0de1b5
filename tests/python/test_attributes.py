# Texture coordinates, normals and materials as a notebook user reads them (attributes.h).
import os

import numpy as np
import pytest

import meshedit

QUAD = """mtllib quad.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl paint
f 1/1 2/2 3/3 4/4
"""


def test_corner_attributes_follow_faces_and_edits(tmp_path):
    (tmp_path / "quad.obj").write_text(QUAD)
    (tmp_path / "quad.mtl").write_text("newmtl paint\nKd 1 0.5 0\nd 0.25\n")
    mesh = meshedit.read(str(tmp_path / "quad.obj"))
    faces = mesh.faces()
    uv = mesh.texcoords()
    assert uv.shape == (4, 2)
    # The corner of face 0 at vertex faces[0][i] has the UV the file gave that vertex.
    expected = {0: (0, 0), 1: (1, 0), 2: (1, 1), 3: (0, 1)}
    for i, v in enumerate(faces[0]):
        assert tuple(uv[i]) == expected[v]
    assert mesh.corner_normals() is None
    assert list(mesh.face_materials()) == [0]
    assert mesh.materials() == [{"name": "paint", "base_colour": (1.0, 0.5, 0.0, 0.25),
                                 "texture": "", "texcoord_set": 0}]
    # A poke's centre blends the four corners: UV (0.5, 0.5) on the four new corners.
    mesh.poke(0)
    uv = mesh.texcoords()
    faces = mesh.faces()
    centre = 4
    at_centre = [tuple(uv[3 * f + i]) for f in range(len(faces)) for i in range(3)
                 if faces[f][i] == centre]
    assert at_centre == [(0.5, 0.5)] * 4
    assert list(mesh.face_materials()) == [0, 0, 0, 0]
    assert np.isfinite(uv).all()


def test_meshes_without_attributes_answer_none():
    mesh = meshedit.Mesh.from_arrays(np.eye(3), np.array([[0, 1, 2]]))
    assert mesh.texcoords() is None and mesh.face_materials() is None
    assert mesh.texcoords(1) is None
    assert mesh.materials() == []


CUBE_2UVS = "/usr/share/assimp/models/Collada/cube_with_2UVs.DAE"


def test_second_texture_coordinate_set_reads_as_set_1():
    if not os.path.exists(CUBE_2UVS):
        pytest.skip(CUBE_2UVS + " is absent (Debian package assimp-testmodels)")
    mesh = meshedit.read(CUBE_2UVS)
    first, second = mesh.texcoords(), mesh.texcoords(1)
    assert first.shape == second.shape == (36, 2)
    assert not np.array_equal(first, second)
    with pytest.raises(ValueError):
        mesh.texcoords(2)
