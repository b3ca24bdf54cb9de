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

from ..part.part import MissingDependency, Output, sink_heads, sink_tools

DEFAULT_THICKNESS = 3.0


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
