"""3D outputs: each part extruded by its thickness with ``manifold3d`` (``Manifold.extrude``),
written as STL (all bodies in one binary STL) or 3MF (one object per part, named after it) with
``trimesh`` (a core dependency, imported only here: ``aidl check`` and SVG do not load it).
trimesh's 3MF writer needs ``networkx`` and ``lxml`` (the ``mesh`` extra); without them
:func:`to_3mf` raises :class:`~.part.MissingDependency` naming the install line.

The profile extruded is the part's boolean result (circles as chords within
:data:`~aidl_lang.geometry.shapes.tessellate.CHORD_TOL`), so the volume is the profile's area times the
thickness, and each body is watertight (Manifold guarantees a manifold mesh).  Units: mm.
"""
from __future__ import annotations

import numpy as np

from ..part.part import Circle, Loop, MissingDependency, Output, sink_heads, sink_tools
from ..part.build.sunk import DEFAULT_THICKNESS


# What a part's solid costs beyond its writer's per-vertex figure (issue 110: the STL of a 70 x
# 70 grid of countersunk 3 mm holes was priced 1.4 M work units and took 128 s of CPU, past the
# backstop; at AIDL_CPU_SCALE=3 the n = 55 one was written on one machine, E0304 on another).
# Measured with manifold3d 3.5 on the 2-core reference machine under load (9 jobs), CPU time:
# - ``Manifold.extrude`` triangulates the section's faces: about TRIANGULATE_PER_VL s per
#   vertex times loop (its holes are bridged one by one) plus TRIANGULATE_PER_VV per vertex
#   squared: a 10 mm grid of 3 mm holes, n x n (V = 39 n^2, L = n^2 + 1): n = 20 0.10-0.14 s,
#   30 0.29-0.38 s, 40 0.8-1.9 s, 55 5.5-10.4 s, 70 15-34 s; 20 x 20 holes of 600 chords
#   (V = 240,000, L = 401) 6.6 s, 40 x 40 of 150 chords 7.9 s, 80 x 80 of 8 chords 1.6 s;
# - the countersinks' cones and counterbores' steps (:func:`~..part.part.sink_tools`): built,
#   united (``batch_boolean``) and subtracted from the extruded part, then their rims
#   written: SECONDS_PER_TOOL_VERTEX a vertex of the tools (2 rings of the hole's chords
#   each): 400 / 900 / 1,600 / 3,025 / 4,900 cones of 78 vertices 1.0 / 2.6 / 5.7 / 11 /
#   20 s, 3.2-3.7 ms a cone, linear.
TRIANGULATE_PER_VL = 3e-8
TRIANGULATE_PER_VV = 1e-10
SECONDS_PER_TOOL_VERTEX = 50e-6


def _trimesh():
    try:
        import trimesh
    except ImportError:         # a core dependency: only a damaged install lacks it
        raise MissingDependency("STL and 3MF output need trimesh: pip install 'trimesh>=4.0' "
                                "(or reinstall aidl-lang)") from None
    return trimesh


def bodies(output: Output, thickness: float | None = None,
           assembled: bool = False) -> list[tuple[str, object]]:
    """(part name, ``trimesh.Trimesh``) per solid part.  ``thickness`` (mm) overrides the
    parts' own; without either, :data:`DEFAULT_THICKNESS`.  ``assembled``: each body moved
    by its part's placement (the booleans' ``Drawing.placement``; the sheet where none) after
    its ``Bend``s (``Drawing.bends``: :func:`~..part.placement.bend_points`, cut across its bend
    zones so every chord is within ``CHORD_TOL`` of the bent surface)."""
    import manifold3d as mf
    trimesh = _trimesh()
    d = output.drawing
    where = (getattr(d, "placement", None) or {}) if assembled and d is not None else {}
    bent = (getattr(d, "bends", None) or {}) if assembled and d is not None else {}
    from ...geometry.shapes.tessellate import CHORD_TOL
    from ..part.build.placement import bend_points, refine_for_bends
    out = []
    heads = sink_heads(output)
    for p in output.parts:
        if p.kind != "solid" or p.shape is None or p.shape.is_empty():
            continue
        t = float(thickness or p.thickness or DEFAULT_THICKNESS)
        m = mf.Manifold.extrude(p.shape, t)
        tools = sink_tools([h for h in heads if h[1].part == p.name], t)
        if tools:           # the countersinks' cones and the counterbores' steps, cut
            m = m - mf.Manifold.batch_boolean(tools, mf.OpType.Add)
        bends = bent.get(p.name)
        mesh = m.to_mesh64()
        v = _exact(np.asarray(mesh.vert_properties, dtype=float)[:, :3], p.loops)
        f = np.asarray(mesh.tri_verts, dtype=np.int64)
        if bends:
            v, f = refine_for_bends(v, f, bends, t, CHORD_TOL)
            flat, v = v, bend_points(v, bends, t)
            f = _weld_ends(flat, v, f)
        M = where.get(p.name)
        if M is not None:
            v = v @ M[:3, :3].T + M[:3, 3]
        tm = trimesh.Trimesh(vertices=v, faces=f, process=False)
        if bends:
            tm.remove_unreferenced_vertices()
        out.append((p.name, tm))
    return out


def solid_seconds(output: Output, per_vertex: float) -> float:
    """An estimate of the CPU seconds (reference machine) of the 3D writers' bodies of
    ``output`` (:func:`bodies`, the GLB's scene alike): ``per_vertex`` s per vertex of each
    solid part's section (the writer's own figure: extruding, re-reading, encoding), its
    faces' triangulation (:data:`TRIANGULATE_PER_VL` x vertices x loops +
    :data:`TRIANGULATE_PER_VV` x vertices squared) and its countersinks' and counterbores'
    tools (:data:`SECONDS_PER_TOOL_VERTEX` a vertex).  Counted from the output alone (no
    Manifold call): the same on every machine, so the work budget decides (issue 110)."""
    seconds = 0.0
    for p in output.parts:
        if p.kind != "solid" or p.shape is None or p.shape.is_empty():
            continue
        v, loops = float(p.shape.num_vert()), float(p.shape.num_contour())
        seconds += per_vertex * v + TRIANGULATE_PER_VL * v * loops + TRIANGULATE_PER_VV * v * v
    return seconds + tool_seconds(output)[1]


def tool_seconds(output: Output) -> tuple[int, float]:
    """``(tools, seconds)``: how many countersinks and counterbores of ``output`` cut a tool
    from its solid (:func:`~..part.part.sink_tools`: a cone or a step), and what cutting them
    costs (reference-machine CPU seconds, :data:`SECONDS_PER_TOOL_VERTEX` a vertex of a tool:
    two rings of its hole's chords)."""
    chords: dict = {}
    tools = vertices = 0
    for _, sk in sink_heads(output):
        if sk.cone_depth() <= 0:
            continue            # no tool (sink_tools leaves it out)
        n = chords.get(sk.hole_d)
        if n is None:
            n = chords[sk.hole_d] = len(Loop([Circle((0.0, 0.0), sk.hole_d / 2)]).points())
        tools += 1
        vertices += 2 * n
    return tools, vertices * SECONDS_PER_TOOL_VERTEX


def _weld_ends(flat: np.ndarray, v: np.ndarray, f: np.ndarray, tol: float = 1e-6) -> np.ndarray:
    """The faces ``f`` of a bent part whose two ends meet (a wall bent all round: its end
    faces, at the flat sheet's least and greatest x, land on each other, every vertex of their
    rims within ``tol`` mm): both end faces dropped and the one rim's vertices used for the
    other's, so the
    ring is one closed solid (watertight when a reader merges equal vertices) instead of a
    strip touching itself; ``f`` unchanged when the ends do not meet."""
    x = flat[:, 0]
    a = np.flatnonzero(np.abs(x - x.min()) < tol)
    b = np.flatnonzero(np.abs(x - x.max()) < tol)
    ends = np.isin(f, a).all(axis=1) | np.isin(f, b).all(axis=1)
    rim = np.unique(f[~ends])            # the end faces' edges: their vertices other faces hold
    a, b = np.intersect1d(a, rim), np.intersect1d(b, rim)
    if len(a) != len(b) or len(a) < 3 or len(a) > 20_000:
        return f
    d = np.linalg.norm(v[b][:, None, :] - v[a][None, :, :], axis=2)
    near = d.argmin(axis=1)
    if d[np.arange(len(b)), near].max() > tol or len(set(near.tolist())) != len(a):
        return f
    to = np.arange(len(v))
    to[b] = a[near]
    return to[f[~ends]]


def _exact(v: np.ndarray, loops) -> np.ndarray:
    """The extruded vertices ``v`` put back on the exact profile's points: the section handed to
    Manifold is rounded to 1e-8 mm (Clipper's precision), its vertices are the loops' points
    (:meth:`~.part.Loop.points`), so each goes back to the point within 1e-6 mm of it."""
    exact = {}
    for lp in loops:
        for x, y in lp.points():
            exact[(round(float(x), 6), round(float(y), 6))] = (float(x), float(y))
    out = v.copy()
    for i, (x, y) in enumerate(v[:, :2]):
        p = exact.get((round(float(x), 6), round(float(y), 6)))
        if p is not None:
            out[i, 0], out[i, 1] = p
    return out


def to_stl(output: Output, thickness: float | None = None, assembled: bool = False) -> bytes:
    """Binary STL of every solid part, extruded (mm; ``assembled``: placed).  Raises
    :class:`MissingDependency` only on a damaged install (trimesh is a core dependency)."""
    trimesh = _trimesh()
    meshes = [m for _, m in bodies(output, thickness, assembled)]
    if not meshes:
        return trimesh.Trimesh().export(file_type="stl")
    return trimesh.util.concatenate(meshes).export(file_type="stl")


def to_3mf(output: Output, thickness: float | None = None, assembled: bool = False) -> bytes:
    """3MF with one object per solid part (named after the part; mm; ``assembled``: each
    placed, as on the sheet where the program places nothing).  Raises
    :class:`MissingDependency` without ``networkx`` or ``lxml`` (the ``mesh`` extra)."""
    trimesh = _trimesh()
    try:
        import networkx  # noqa: F401  (trimesh's 3MF exporter needs both)
        import lxml.etree  # noqa: F401
    except ImportError as e:
        raise MissingDependency(f"3MF output needs networkx and lxml (no {e.name}): "
                                "pip install 'aidl-lang[mesh]'") from None
    scene = trimesh.Scene()
    for name, m in bodies(output, thickness, assembled):
        scene.add_geometry(m, geom_name=name, node_name=name)
    return scene.export(file_type="3mf")


def write_stl(output: Output, options) -> bytes:
    """The registry's ``.stl`` (:data:`~.FORMATS`): :func:`to_stl` with the
    :class:`~.Options` ``thickness`` and ``assembled``."""
    return to_stl(output, options.thickness, options.assembled)


def write_3mf(output: Output, options) -> bytes:
    """The registry's ``.3mf`` (:data:`~.FORMATS`): :func:`to_3mf` with the
    :class:`~.Options` ``thickness`` and ``assembled``."""
    return to_3mf(output, options.thickness, options.assembled)
