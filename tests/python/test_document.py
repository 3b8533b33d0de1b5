# meshedit.Document: undo and redo, bit for bit, of local and whole-mesh steps.
import numpy as np
import pytest

import meshedit


def state(mesh):
    faces = mesh.faces()
    return mesh.V.copy(), [list(f) for f in faces], mesh.info()["edges"]


def same(a, b):
    return np.array_equal(a[0], b[0]) and a[1] == b[1] and a[2] == b[2]


def test_undo_redo_local_and_whole_mesh_steps(sample):
    doc = meshedit.Document(meshedit.read(sample("cube.dae")))
    states = [state(doc.mesh)]
    assert doc.flip(0, 6) == (4, 2)  # what the step selected, as Mesh methods return it
    states.append(state(doc.mesh))
    doc.apply("split:0-1,poke:f3")
    states.append(state(doc.mesh))
    doc.loop()
    states.append(state(doc.mesh))
    doc.extrude(f=5, height=0.2)
    states.append(state(doc.mesh))
    assert doc.session == ["flip:0-6", "split:0-1,poke:f3", "loop", "extrude:f5:0.2"]
    for expected in reversed(states[:-1]):
        doc.undo()
        assert same(state(doc.mesh), expected)
        assert doc.mesh.validate() is None
    assert not doc.can_undo
    with pytest.raises(IndexError, match="nothing to undo"):
        doc.undo()
    for expected in states[1:]:
        doc.redo()
        assert same(state(doc.mesh), expected)
    assert not doc.can_redo


def test_a_refused_step_leaves_document_and_history_alone(sample):
    doc = meshedit.Document(meshedit.read(sample("bowl.dae")))
    doc.split(0, 1)
    before = state(doc.mesh)
    with pytest.raises(meshedit.Refused):
        doc.apply("poke:f3,flip:121-122")
    assert same(state(doc.mesh), before)
    assert doc.session == ["split:0-1"]


def test_an_edit_behind_the_documents_back_drops_the_history(sample):
    mesh = meshedit.read(sample("cube.dae"))
    doc = meshedit.Document(mesh)
    doc.flip(0, 6)
    mesh.loop()
    with pytest.raises(RuntimeError, match="edited outside the document"):
        doc.undo()
    assert not doc.can_undo
    with pytest.raises(TypeError, match="expected a meshedit.Mesh"):
        meshedit.Document("cube.dae")
