"""Where the parts go in the assembled product: the matrices of ``Place``.

In: a part's structure and the solved values ``x`` (its frame offsets), its ancestors'
``Place`` (a position in mm and rotations about x, y, z in radians, fixed axes).  Out: the
4x4 matrix from the flat sheet (x, y in mm, z up through the thickness) to the assembled
product (:func:`placement_matrix`), read by the booleans into ``Drawing.placement`` for the
3D writers and the fit check (:mod:`aidl_lang.output.fabrication.assembly`).
"""
from __future__ import annotations

import math

import numpy as np

from ...geometry.model import Structure


def rotation_matrix(rx: float, ry: float, rz: float) -> np.ndarray:
    """The 3x3 rotation turning about x by ``rx``, then about y by ``ry``, then about z by
    ``rz`` (radians, fixed axes: ``Rz @ Ry @ Rx``); quarter turns are exact (cos 90 deg is 0,
    not 6e-17), so a box's panels land on the design's numbers to the last bit."""
    def cs(a):
        q = a / (math.pi / 2)
        if abs(q - round(q)) < 1e-12:
            return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(round(q)) % 4]
        return math.cos(a), math.sin(a)
    (cx, sx), (cy, sy), (cz, sz) = cs(rx), cs(ry), cs(rz)
    Rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]], dtype=float)
    Ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]], dtype=float)
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]], dtype=float)
    return Rz @ Ry @ Rx


def placement_matrix(s: Structure, x) -> np.ndarray:
    """The 4x4 matrix taking a point of part ``s`` on the flat sheet (absolute x, y in mm; z
    from 0 up through its thickness) to the assembled product.  Each structure's local frame
    (its points less the sum of its and its ancestors' frame offsets, ``x`` the solved values)
    goes into its parent's by its ``Place`` (rotation, then position) or, unplaced, by its
    frame offset as on the sheet, so a program with no ``Place`` is the sheet itself."""
    chain = [s, *s.ancestors()]
    M = np.eye(4)
    for a in reversed(chain):                  # root first: M maps a's local frame to world
        step = np.eye(4)
        pl = getattr(a, "placement", None)
        if pl is not None:
            step[:3, :3] = rotation_matrix(*pl[1])
            step[:3, 3] = pl[0]
        else:
            step[0, 3], step[1, 3] = x[a.fx], x[a.fy]
        M = M @ step
    ox = sum(float(x[a.fx]) for a in chain)
    oy = sum(float(x[a.fy]) for a in chain)
    to_local = np.eye(4)
    to_local[0, 3], to_local[1, 3] = -ox, -oy
    return M @ to_local
