# Every verb as a method, the edit language, refusals with the CLI's reasons, files alike.
import filecmp

import numpy as np
import pytest

import meshedit


def snapshot(mesh):
    return mesh.V.copy(), [list(f) for f in mesh.faces()]


def test_every_verb_is_a_method():
    for verb in meshedit.verbs():
        assert callable(getattr(meshedit.Mesh, verb["name"])), verb["name"]
        assert callable(getattr(meshedit.Document, verb["name"])), verb["name"]


@pytest.mark.parametrize("call, text", [
    (("flip", (0, 6), {}), "flip:0-6"),
    (("flip", ((0, 6),), {}), "flip:0-6"),
    (("split", (0, 1), {}), "split:0-1"),
    (("dissolve", (), {"v": 12}), "dissolve:v12"),
    (("collapse", (), {"f": 3}), "collapse:f3"),
    (("poke", (7,), {}), "poke:f7"),
    (("extrude", (), {"f": 7, "height": 0.2}), "extrude:f7:0.2"),
    (("extrude", (7, 0.2, 0.5), {}), "extrude:f7:0.2,0.5"),
    (("bevel", (0, 1, 0.25), {}), "bevel:0-1:0.25"),
    (("bevel", (), {"v": 3, "t": 0.25}), "bevel:v3:0.25"),
    (("weld", ((0, 1), (5, 6)), {}), "weld:0-1+5-6"),
    (("fill_fair", (1, 1372), {}), "fill_fair:1-1372"),
    (("move", (3, 1, 2, 3), {}), "move:v3:1,2,3"),
    (("loop", (), {}), "loop"),
    (("loop", (2,), {}), "loop:2"),
    (("loop", (2,), {"uv": "none"}), "loop:2:uv=none"),
    (("catmull_clark", (), {"uv": "corners+1"}), "catmull_clark:uv=corners+1"),
    (("simplify", (0.25,), {}), "simplify:0.25"),
    (("simplify", (0.25,), {"attributes": "blind"}), "simplify:0.25:attributes=blind"),
    (("simplify", (), {"attributes": "aware"}), "simplify:attributes=aware"),
    (("remesh", (), {"rounds": 5}), "remesh:0,5"),
    (("triangulate", (), {}), "triangulate"),
    (("triangulate", (), {"f": 2}), "triangulate:f2"),
    (("extrude_region", ([6, 7, 8], 0.5), {}), "extrude_region:f6+f7+f8:0.5"),
    (("extrude_region", (), {"f": np.array([1, 2]), "height": 1}), "extrude_region:f1+f2:1"),
    (("inset_region", ([6, 7],), {"thickness": 0.25}), "inset_region:f6+f7:0.25"),
    (("simplify_region", ([3, 4, 5],), {"ratio": 0.5}), "simplify_region:f3+f4+f5:0.5"),
    (("loop_region", ([0, 1],), {}), "loop_region:f0+f1"),
    (("subdivide_region", ([4],), {}), "subdivide_region:f4"),
])
def test_calling_convention(call, text):
    verb, args, kwargs = call
    assert meshedit.step_text(verb, *args, **kwargs) == text


def test_bad_calls_are_type_errors():
    with pytest.raises(TypeError, match="unexpected keyword argument 'depth'"):
        meshedit.step_text("extrude", f=1, depth=2)
    with pytest.raises(TypeError, match="at most 0 amounts"):
        meshedit.step_text("flip", 0, 1, 0.5)
    with pytest.raises(TypeError, match="extrude\\(\\) needs height"):
        meshedit.step_text("extrude", f=1, shrink=0.5)
    with pytest.raises(TypeError, match="amounts are numbers"):
        meshedit.step_text("extrude", 1, "high")
    with pytest.raises(TypeError, match="height must be a number"):
        meshedit.step_text("extrude", f=1, height=None)
    with pytest.raises(TypeError, match="at most 0 amounts"):
        meshedit.step_text("dissolve", 12)
    with pytest.raises(TypeError, match="the region is a list of face indices"):
        meshedit.step_text("subdivide_region", 4)
    with pytest.raises(TypeError, match="the region is a list of face indices"):
        meshedit.step_text("subdivide_region", [1.5])


def test_methods_run_the_same_steps_as_the_cli(sample, cli, tmp_path):
    mesh = meshedit.read(sample("cube.dae"))
    assert mesh.flip(0, 6) == (0, 6) or mesh.info()["edges"] == 18
    new_vertex = mesh.split(0, 1)
    assert new_vertex == 8
    mesh.loop()
    mesh.write(tmp_path / "py.obj")
    status, _, err = cli("convert", sample("cube.dae"), tmp_path / "cli.obj",
                         "--ops", "flip:0-6,split:0-1,loop")
    assert status == 0, err
    assert filecmp.cmp(tmp_path / "py.obj", tmp_path / "cli.obj", shallow=False)


def test_apply_and_apply_file(sample, tmp_path):
    a = meshedit.read(sample("cube.dae"))
    a.apply("flip:0-6,split:0-1,loop")
    session = tmp_path / "session.ops"
    session.write_text("# a session\nflip:0-6\nsplit:0-1\n\nloop\n")
    b = meshedit.read(sample("cube.dae"))
    b.apply_file(session)
    assert np.array_equal(a.V, b.V)
    assert np.array_equal(a.faces(), b.faces())


def test_refusal_has_the_cli_reason_and_changes_nothing(sample, cli, tmp_path):
    mesh = meshedit.read(sample("bowl.dae"))
    before = snapshot(mesh)
    with pytest.raises(meshedit.Refused) as error:
        mesh.flip(121, 122)
    assert str(error.value) == "flip:121-122 refused: cannot flip: boundary edge"
    assert isinstance(error.value, RuntimeError)
    status, _, err = cli("convert", sample("bowl.dae"), tmp_path / "x.obj", "--ops", "flip:121-122")
    assert status == 1 and str(error.value) in err
    after = snapshot(mesh)
    assert np.array_equal(before[0], after[0]) and before[1] == after[1]


def test_a_refused_list_changes_nothing(sample):
    mesh = meshedit.read(sample("bowl.dae"))
    before = snapshot(mesh)
    with pytest.raises(meshedit.Refused):
        mesh.apply("split:0-1,poke:f3,flip:121-122")
    after = snapshot(mesh)
    assert np.array_equal(before[0], after[0]) and before[1] == after[1]


def test_bad_steps_are_value_errors_with_the_cli_message(sample, cli, tmp_path):
    mesh = meshedit.read(sample("cube.dae"))
    with pytest.raises(meshedit.SyntaxError) as error:
        mesh.apply("flip:x")
    assert isinstance(error.value, ValueError)
    status, _, err = cli("convert", sample("cube.dae"), tmp_path / "x.obj", "--ops", "flip:x")
    assert status == 2 and str(error.value) in err
    with pytest.raises(meshedit.BadStep, match="flip:0-99"):
        mesh.flip(0, 99)
    with pytest.raises(meshedit.SyntaxError, match="session.ops"):
        (tmp_path / "session.ops").write_text("flip:nope\n")
        mesh.apply_file(tmp_path / "session.ops")
    with pytest.raises(meshedit.IoError):
        mesh.apply_file(tmp_path / "missing.ops")


def test_subdivide_simplify_remesh(sample):
    mesh = meshedit.read(sample("cube.dae"))
    mesh.subdivide(2)
    assert mesh.info()["faces"] == 12 * 16
    mesh.simplify(0.5)
    assert mesh.info()["faces"] <= 12 * 16 * 0.5 + 2
    mesh.remesh()
    assert mesh.validate() is None
    quads = meshedit.read(sample("quadcube.dae"))
    quads.subdivide(1, scheme="catmull_clark")
    assert quads.info()["face_degrees"] == {4: 24}
    with pytest.raises(ValueError, match="scheme"):
        quads.subdivide(1, scheme="butterfly")
    quads.subdivide(1, scheme="linear", uv="all")
    assert quads.info()["faces"] == 96
    with pytest.raises(meshedit.SyntaxError, match="one of none, corners, corners"):
        quads.subdivide(1, scheme="catmull_clark", uv="smooth")
    with pytest.raises(TypeError, match="uv"):
        meshedit.step_text("flip", 0, 6, uv="none")


def test_notices_are_warnings(sample):
    mesh = meshedit.read(sample("cube.dae"))
    with pytest.warns(meshedit.Notice, match="simplify:0.01: stopped at 4 faces"):
        mesh.simplify(0.01)
    again = meshedit.read(sample("cube.dae"))
    assert again.apply("simplify:0.01") == [
        "simplify:0.01: stopped at 4 faces: no further collapse keeps the mesh valid and unfolded"]


def test_problems_are_the_clis_and_a_fair_fill_closes_the_hole(sample, cli):
    # The bowl is open: one hole, as `meshedit check --problems` says; filled and faired by
    # the verb method, nothing is left.
    mesh = meshedit.read(sample("bowl.dae"))
    problems = mesh.problems()
    assert [p["kind"] for p in problems] == ["hole"]
    assert problems[0]["element"].startswith("edge ")
    status, out, _ = cli("check", sample("bowl.dae"), "--problems")
    assert status == 1 and problems[0]["text"] in out
    mesh.fill_holes_fair()
    assert mesh.problems() == []
    assert mesh.validate() is None


def test_stitch_closes_a_crack_as_the_cli_does():
    # The lower triangle's top side runs from (2,0) to (0,0); the upper two triangles meet at
    # (1,0) on it with their own corners at its ends (tests/repair/stitch_test.cpp).
    V = np.array([[0, 0, 0], [2, 0, 0], [1, -1, 0], [0, 0, 0], [2, 0, 0], [1, 0, 0], [1, 1, 0]],
                 dtype=float)
    mesh = meshedit.Mesh.from_arrays(V, [[0, 2, 1], [3, 5, 6], [5, 4, 6]])
    assert len(mesh.problems()) > 0
    mesh.stitch()
    assert mesh.validate() is None
    assert len(mesh.V) == 5 and len(mesh.faces()) == 4
    assert [p["kind"] for p in mesh.problems()] == ["hole"]  # the outline only
    before = snapshot(mesh)
    with pytest.raises(meshedit.Refused, match="less than 0.5 of an edge's length"):
        mesh.stitch(ratio=0.5)
    after = snapshot(mesh)
    assert np.array_equal(before[0], after[0]) and before[1] == after[1]
