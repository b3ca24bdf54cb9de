"""GLB writer: binary glTF of the assembled product (:mod:`..assembly`), one named node per
part, its mesh (``trimesh``, from :func:`.mesh.bodies`) in the part's colour of the flat
view (mm; glTF's y is up, so a viewer turns the product's z up itself)."""
from __future__ import annotations

from ..fabrication.assembly import _rgba, colours
from ..part.part import Output, OutputError, sink_heads, sink_tools
from .mesh import _trimesh, bodies


def scene(output: Output, thickness: float | None = None, assembled: bool = True):
    """A ``trimesh.Scene`` of the assembled product (``assembled=False``: the parts as on the
    sheet): one node per part, named after it, its mesh coloured like the part in the flat
    view."""
    trimesh = _trimesh()
    colour = colours(output)
    sc = trimesh.Scene()
    for name, m in bodies(output, thickness, assembled):
        c = colour.get(name)
        if c is not None:
            m.visual = trimesh.visual.ColorVisuals(m, face_colors=_rgba(c))
        sc.add_geometry(m, geom_name=name, node_name=name)
    return sc


def to_glb(output: Output, thickness: float | None = None, assembled: bool = True) -> bytes:
    """Binary glTF (GLB) of the assembled product (``assembled=False``: as on the sheet):
    one named node per part, its mesh in the part's colour (mm; glTF's y is up, so a viewer
    turns the product's z up itself)."""
    return scene(output, thickness, assembled).export(file_type="glb")


def write(output: Output, options) -> bytes:
    """The registry's ``.glb`` (:data:`~.FORMATS`): :func:`to_glb` with the
    :class:`~.Options` ``thickness`` and ``assembled``."""
    return to_glb(output, options.thickness, options.assembled)


# A view's GLB (aidl studio's 3D pane): the product spans about this many pixels; a chord
# may leave its curve by a quarter of one (never less than the exact writers' CHORD_TOL)
VIEW_PIXELS = 1000


def view_tolerance(output: Output) -> float:
    """The chord tolerance (mm) of :func:`to_view_glb`: a quarter pixel of a view
    :data:`VIEW_PIXELS` wide across the drawing's diagonal, at least ``CHORD_TOL``."""
    import math
    from ...geometry.shapes.tessellate import CHORD_TOL
    x0, y0, x1, y1 = output.bounds()
    return max(CHORD_TOL, math.hypot(x1 - x0, y1 - y0) / VIEW_PIXELS / 4)


def to_view_glb(output: Output, thickness: float | None = None, assembled: bool = True,
                tol: float | None = None) -> bytes:
    """A GLB for a 3D *view* (aidl studio's pane), smaller and quicker than :func:`to_glb`:
    circles and arcs in as few chords as the view needs (within ``tol`` mm, default
    :func:`view_tolerance`; every vertex still on the exact curve), one mesh per distinct
    shape (parts of the same outline and thickness, such as a planetary set's planets, share
    one mesh, each part a node moved to its place), and each part's colour a material
    (``baseColorFactor``, linear) instead of a colour per vertex; a part with ``Bend``s
    shown bent, its chords within ``tol`` of the bent surface.  One named node per solid
    part, as :func:`to_glb` (mm; glTF's y is up, the viewer turns the product's z up).
    Not a download: the files stay exact (:func:`to_glb`).  Raises
    :class:`~..part.part.OutputError` when there is no solid part (a drawing of lines only)."""
    import hashlib

    import manifold3d as mf
    import numpy as np

    from ..fabrication.assembly import bends_of, placements
    from ..fabrication.assembly import bent as bend
    from ..part.build.sunk import DEFAULT_THICKNESS
    trimesh = _trimesh()
    tol = view_tolerance(output) if tol is None else tol
    colour = colours(output)
    where = placements(output) if assembled else {}
    bent = bends_of(output) if assembled else {}
    sc = trimesh.Scene()
    shapes: dict[bytes, str] = {}
    node_colour: dict[str, str] = {}
    heads = sink_heads(output)
    for p in output.parts:
        if p.kind != "solid" or not p.loops:
            continue
        polys = [lp.points(tol) for lp in p.loops]
        polys = [q for q in polys if len(q) >= 3]
        if not polys:
            continue
        origin = polys[0].min(axis=0)
        local = [q - origin for q in polys]
        t = float(thickness or p.thickness or DEFAULT_THICKNESS)
        bends = [(at - float(origin[0]), a, r) for at, a, r in bent.get(p.name, ())]
        # its countersinks and counterbores, in the part's own frame (issue 102)
        sunk = [((c[0] - float(origin[0]), c[1] - float(origin[1])), r)
                for c, r in heads if r.part == p.name]
        h = hashlib.sha1(repr((round(t, 9), bends, [(np.round(c, 6).tolist(), r.kind,
                                                     r.diameter, r.angle, r.depth)
                                                    for c, r in sunk])).encode())
        for q in local:
            h.update(np.round(q, 6).tobytes())
        key = h.digest()
        T = np.eye(4)
        T[:2, 3] = origin
        M = where.get(p.name)
        if M is not None:
            T = np.asarray(M, dtype=float) @ T
        geom = shapes.get(key)
        if geom is None:
            m = mf.Manifold.extrude(mf.CrossSection([q.tolist() for q in local],
                                                    mf.FillRule.NonZero), t)
            tools = sink_tools(sunk, t)
            if tools:
                m = m - mf.Manifold.batch_boolean(tools, mf.OpType.Add)
            m = (bend(m, bends, t, tol) if bends else m).to_mesh64()
            mesh = trimesh.Trimesh(vertices=np.asarray(m.vert_properties)[:, :3],
                                   faces=np.asarray(m.tri_verts, dtype=np.int64), process=False)
            if not len(mesh.faces):
                continue
            geom = shapes[key] = f"shape{len(shapes)}"
            sc.add_geometry(mesh, geom_name=geom, node_name=p.name, transform=T)
        else:
            sc.graph.update(frame_to=p.name, frame_from=sc.graph.base_frame, matrix=T,
                            geometry=geom)
        node_colour[p.name] = colour.get(p.name, "#607d8b")

    if not node_colour:
        raise OutputError("no solid part to show in 3D (only lines: a drawing)")

    def materials(tree: dict) -> None:
        # a mesh per part that shares its shape's accessors, with the part's colour
        mats, meshes, seen = [], [], {}
        for node in tree.get("nodes", []):
            if "mesh" not in node or node.get("name") not in node_colour:
                continue
            c = node_colour[node["name"]]
            if c not in seen:
                seen[c] = len(mats)
                rgb = [_linear(int(c[i:i + 2], 16) / 255) for i in (1, 3, 5)]
                mats.append({"pbrMetallicRoughness": {"baseColorFactor": rgb + [1.0],
                                                      "metallicFactor": 0.0,
                                                      "roughnessFactor": 0.9}})
            base = tree["meshes"][node["mesh"]]
            meshes.append({"name": node["name"], "primitives": [
                {**prim, "material": seen[c]} for prim in base["primitives"]]})
            node["mesh"] = len(meshes) - 1
        tree["meshes"] = meshes or tree.get("meshes", [])
        tree["materials"] = mats
    return sc.export(file_type="glb", tree_postprocessor=materials)


def _linear(c: float) -> float:
    """An sRGB channel (0-1) as glTF's linear ``baseColorFactor`` wants it (IEC 61966-2-1)."""
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
