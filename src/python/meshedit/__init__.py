"""MeshEdit from Python: halfedge meshes, their file formats and the edit language.

    import meshedit
    mesh = meshedit.read("dae/cube.dae")
    mesh.flip(0, 6)            # every verb of the edit language is a method
    mesh.loop()
    mesh.write("cube.obj")     # returns what the format could not keep

docs/python.md has the whole story. Every edit does what it says or raises with the reason
the command line gives: meshedit.Refused (the operation said no; the mesh is unchanged),
meshedit.BadStep (the step names an element the mesh does not have) and meshedit.SyntaxError
(a malformed step), both ValueErrors; reading and writing raise meshedit.IoError (an OSError).
"""

import numbers as _numbers
import warnings as _warnings

from ._meshedit import (  # noqa: F401
    BadStep,
    Document,
    IoError,
    Mesh,
    Refused,
    SyntaxError,
    __version__,
    amount_text,
    field_names,
    read,
    set_threads,
    threads,
    verbs,
)

for _cls in (BadStep, Document, IoError, Mesh, Refused, SyntaxError):
    _cls.__module__ = "meshedit"  # tracebacks say meshedit.Refused, not meshedit._meshedit.Refused

__all__ = ["read", "Mesh", "Document", "IoError", "Refused", "BadStep", "SyntaxError",
           "Notice", "verbs", "field_names", "step_text", "render", "set_threads", "threads"]


class Notice(UserWarning):
    """What an edit did besides its job ("loop: triangulated 6 faces first")."""


# Keyword names of each verb's amounts, in the language's order (`extrude:f7:0.2,0.5` is
# mesh.extrude(f=7, height=0.2, shrink=0.5)); a verb not listed takes them positionally only.
AMOUNT_NAMES = {
    "extrude": ("height", "shrink"),
    "inset": ("shrink",),
    "bevel": ("t",),
    "move": ("x", "y", "z"),
    "simplify": ("ratio", "max_error", "feature_angle"),  # ratio: a share below 1, or faces
    "remesh": ("length", "rounds", "feature_angle"),
    "crease_by_angle": ("degrees",),
    "extrude_region": ("height",),
    "inset_region": ("thickness",),
    "simplify_region": ("ratio",),  # a share of the region's faces, below 1
    "merge_by_distance": ("tolerance", "absolute"),  # absolute=1: a distance, not a share
    "stitch": ("ratio",),  # a share of each edge's length
    "remove_small": ("faces",),
    "fill_holes": ("max_edges",),
}

_VERBS = {verb["name"]: verb for verb in verbs()}


def _is_index(x):
    return isinstance(x, _numbers.Integral) and not isinstance(x, bool)


def _edge_text(edge, verb):
    try:
        a, b = edge
    except (TypeError, ValueError):
        raise TypeError(f"{verb}(): an edge is a pair of vertex indices, got {edge!r}") from None
    if not (_is_index(a) and _is_index(b)):
        raise TypeError(f"{verb}(): an edge is a pair of vertex indices, got {edge!r}")
    return f"{int(a)}-{int(b)}"


def _integer_dtype(x):
    return getattr(getattr(x, "dtype", None), "kind", "") in ("i", "u")


def _region_text(faces, verb, info):
    """A region's faces as the language writes them: "f6+f7+f8"."""
    try:
        indices = [int(x) if _is_index(x) or _integer_dtype(x) else None for x in faces]
    except TypeError:
        indices = [None]
    if not indices or None in indices:
        raise TypeError(f"{verb}(): the region is a list of face indices ({info['syntax']})")
    return "+".join(f"f{x}" for x in indices)


def step_text(verb, *args, v=None, f=None, e=None, levels=None, uv=None, attributes=None,
              **amounts):
    """The edit-language step that mesh.<verb>(*args, **kwargs) runs.

    Elements: an edge as two vertex indices (`flip(0, 6)`, or `e=(0, 6)`), a weld's two edges
    as two pairs (`weld((0, 1), (5, 6))`), a vertex as `v=12`, a face as `f=7` (or positionally
    when the verb takes only faces or only vertices: `poke(7)`). Amounts follow, positionally or
    by name (AMOUNT_NAMES); subdivision verbs take `levels` (`loop(2)`) and `uv`, how texture
    coordinates are refined (`loop(2, uv="none")`: none, corners, corners+1, corners+2,
    boundaries or all); simplify takes `attributes`, "aware" (the default: UV seams, colours
    and materials weigh) or "blind" (positions only); region verbs take the
    faces as a list or array of face indices (`extrude_region([6, 7, 8], 0.5)`, or `f=[...]`).
    """
    info = _VERBS.get(verb)
    if info is None:
        raise ValueError(f"unknown verb {verb!r}")
    args = list(args)
    target = ""
    if info.get("region"):
        target = _region_text(f if f is not None else (args.pop(0) if args else None), verb, info)
    elif e is not None:
        target = _edge_text(e, verb)
    elif v is not None:
        if not _is_index(v):
            raise TypeError(f"{verb}(): v must be a vertex index, got {v!r}")
        target = f"v{int(v)}"
    elif f is not None:
        if not _is_index(f):
            raise TypeError(f"{verb}(): f must be a face index, got {f!r}")
        target = f"f{int(f)}"
    elif args and (info["edge"] or info["edge_pair"]) and isinstance(args[0], (tuple, list)):
        target = _edge_text(args.pop(0), verb)
        if info["edge_pair"] and args and isinstance(args[0], (tuple, list)):
            target += "+" + _edge_text(args.pop(0), verb)
    elif (info["edge"] or info["edge_pair"]) and len(args) >= 2 and all(
            _is_index(x) for x in args[:2]):
        target = _edge_text(args[:2], verb)
        del args[:2]
        if info["edge_pair"] and len(args) >= 2 and all(_is_index(x) for x in args[:2]):
            target += "+" + _edge_text(args[:2], verb)
            del args[:2]
    elif args and _is_index(args[0]) and not info["levels"] and (info["vertex"] != info["face"]) \
            and not info["edge"] and not info["edge_pair"]:
        kind = "v" if info["vertex"] else "f"
        target = f"{kind}{int(args.pop(0))}"

    if uv is not None and not info.get("uv"):
        raise TypeError(f"{verb}() got an unexpected keyword argument 'uv'")
    if uv is not None and not isinstance(uv, str):
        raise TypeError(f"{verb}(): uv must be a name such as 'corners', got {uv!r}")
    if attributes is not None and not info.get("attributes"):
        raise TypeError(f"{verb}() got an unexpected keyword argument 'attributes'")
    if attributes is not None and attributes not in ("aware", "blind"):
        raise ValueError(f"{verb}(): attributes must be 'aware' or 'blind', got {attributes!r}")
    if info["levels"]:
        if args and levels is None:
            levels = args.pop(0)
        if levels is not None or uv is not None:
            if levels is not None and not _is_index(levels):
                raise TypeError(f"{verb}(): levels must be an integer, got {levels!r}")
            if args:
                raise TypeError(f"{verb}() takes one count ({info['syntax']}), got more")
            text = verb if levels is None else f"{verb}:{int(levels)}"
            return text if uv is None else f"{text}:uv={uv}"

    names = AMOUNT_NAMES.get(verb, ())
    values = []
    for x in args:
        if not isinstance(x, _numbers.Real) or isinstance(x, bool):
            raise TypeError(f"{verb}(): amounts are numbers ({info['syntax']}), got {x!r}")
        values.append(float(x))
    for name in amounts:
        if name not in names:
            raise TypeError(f"{verb}() got an unexpected keyword argument {name!r}")
    for i, name in enumerate(names):
        if name in amounts:
            if i < len(values):
                raise TypeError(f"{verb}() got {name} twice")
            while len(values) < i:
                if len(values) < info["min_amounts"]:
                    raise TypeError(f"{verb}() needs {names[len(values)]}")
                values.append(info["defaults"][len(values)])
            if not isinstance(amounts[name], _numbers.Real) or isinstance(amounts[name], bool):
                raise TypeError(f"{verb}(): {name} must be a number, got {amounts[name]!r}")
            values.append(float(amounts[name]))
    if len(values) > info["max_amounts"]:
        raise TypeError(f"{verb}() takes at most {info['max_amounts']} amounts "
                        f"({info['syntax']}), got {len(values)}")
    text = verb
    if target:
        text += ":" + target
    if values:
        text += ":" + ",".join(amount_text(x) for x in values)
    if attributes is not None:
        text += ":attributes=" + attributes
    return text


def _verb_method(name, run):
    info = _VERBS[name]

    def method(self, *args, **kwargs):
        return run(self, step_text(name, *args, **kwargs))

    method.__name__ = name
    method.__qualname__ = name
    names = AMOUNT_NAMES.get(name)
    method.__doc__ = (f"The step `{info['syntax']}`: {info['help']}."
                      + (f" Amounts: {', '.join(names)}." if names else ""))
    return method


def _run_step(target, text):
    """Runs one step on a Mesh or a Document; returns what it selected, warns its notices."""
    selected, notices = target._step(text)
    for notice in notices:
        _warnings.warn(notice, Notice, stacklevel=3)
    return selected


for _name in _VERBS:
    setattr(Mesh, _name, _verb_method(_name, _run_step))
    setattr(Document, _name, _verb_method(_name, _run_step))


def _subdivide(self, levels=1, scheme="loop", uv=None):
    """`levels` levels of subdivision: scheme "loop", "catmull_clark" or "linear"; `uv` how
    texture coordinates are refined (OpenSubdiv's face-varying options: "none", "corners" (the
    default), "corners+1", "corners+2", "boundaries", "all")."""
    if scheme not in ("loop", "catmull_clark", "linear"):
        raise ValueError(f"scheme: expected 'loop', 'catmull_clark' or 'linear', got {scheme!r}")
    return getattr(self, scheme)(levels, uv=uv)


Mesh.subdivide = _subdivide
Document.subdivide = _subdivide


from ._render import render  # noqa: E402
