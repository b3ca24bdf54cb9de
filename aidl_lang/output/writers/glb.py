"""GLB writer: binary glTF of the assembled product (:mod:`..assembly`), one named node per
part, its mesh (``trimesh``, from :func:`.mesh.bodies`) in the part's colour of the flat
view (mm; glTF's y is up, so a viewer turns the product's z up itself)."""
from __future__ import annotations

from ..assembly import _rgba, colours
from ..part import Output
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
