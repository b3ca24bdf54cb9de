"""W0519's fix for a slit whose two sides meet at its floor (issue 84).

A slit between two lobes that come close is closed by moving one onto the other or opened by
moving it away (:func:`slit_fix` gives both, with the distances).  A *nick* is different:
the two sides meet at the slit's floor at a sharp inner corner and taper apart from there
(an arm joined low on a plate's rounded corner).  Moving one away parts them (W0504) and
moving it in only moves the nick; rounding that corner alone by ``min_wall``
(``Fillet(at=[corner], radius=...)``) fills the narrow part and nothing else.  Where one side
leaves the other along its tangent (a cusp: an arm flush with the straight side of a
rounded corner) no fillet has a corner to round and the hint gives no number.
"""
from __future__ import annotations

import math

from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing

NICK_TURN = 2 * math.pi / 3     # rad: a slit's two sides meet at a nick's floor at a corner
                                # sharper than 60 degrees (they turn by more than 120)
CUSP = 1e-6                     # rad: a turn within this of pi is a cusp


def _nick_corners(d: Drawing, s: Structure) -> list:
    """The corners in mm of part ``s``'s final exact outline where a slit's two sides can
    meet: each concave join sharper than 60 degrees (turning right by more than
    :data:`NICK_TURN`), as (x, y, cusp) (``cusp``: the sides leave it along one tangent,
    which no fillet rounds).  Exact: ``Fillet(at=[...])`` matches it."""
    from ....geometry.shapes.curves import Circle, turn_between
    shape = d.shapes.get(s)
    if shape is None or shape.is_empty():
        return []
    out = []
    for loops in d.exact.loops_of([shape]):
        for lp in loops:
            segs = lp.segments
            if len(segs) < 2 or any(isinstance(g, Circle) for g in segs):
                continue                # a whole circle has no corner
            for k in range(len(segs)):
                # outer loops run counter-clockwise, openings clockwise: the material is
                # on the left, so a concave (inner) corner turns right
                turn = turn_between(segs[k - 1], segs[k])
                if turn >= -NICK_TURN and abs(turn) < math.pi - CUSP:
                    continue            # a cusp (a line into an arc tangent to it, back
                                        # the way it came) turns by +-pi either way
                c = segs[k].start
                out.append((float(c[0]), float(c[1]), abs(turn) >= math.pi - CUSP))
    return out


# a slit longer than this many minimum walls is a seam: rounding its corner fills it all
SEAM = 4


def _nick_corner(corners: list, at, reach: float):
    """Of ``corners`` (:func:`_nick_corners`), the one nearest to ``at`` (a slit's narrowest
    place) within ``reach`` mm, or None: a slit whose sides do not meet there (two lobes
    that come close; a floor between them, whose corners are square)."""
    best, far = None, reach
    for c in corners:
        r = math.hypot(c[0] - at[0], c[1] - at[1])
        if r <= far:
            best, far = c, r
    return best


def slit_fix(d: Drawing, s: Structure, at, w: float, t: float, names: list,
             found: dict | None = None, length: float = 0.0) -> str:
    """The fix W0519's hint gives for a slit of part ``s`` whose narrowest place is ``at``
    (x, y in mm), ``w`` mm wide, at minimum ``t`` mm, ``length`` mm long, between the shapes
    ``names`` (their labels, quoted): a nick's corner rounded (and, for a slit longer than
    :data:`SEAM` t, the two ended t apart instead), a cusp described without a number, else the
    moves that close or open the gap.  ``found`` keeps each part's corners between calls
    (``id(s)`` -> :func:`_nick_corners`: 860 slits of one part searched its whole outline
    each, 16 s)."""
    found = {} if found is None else found
    if id(s) not in found:
        found[id(s)] = _nick_corners(d, s)
    apex = _nick_corner(found[id(s)], at, 2 * t)
    if apex is not None:                # as the program writes it (a layout moves the part)
        from ..common import written
        apex = (*written(s, apex[0], apex[1]), *apex[2:])
    if apex is not None and apex[2]:
        # a cusp: one side leaves the other along its tangent (an arm flush with a
        # rounded corner's straight side); a move only slides the cusp along, a fillet
        # has no corner to round there: no number would be right
        return (f"the two sides part along one tangent at ({apex[0]:.2f}, {apex[1]:.2f}) (a "
                f"cusp), so moving {names[0]} or {names[-1]} only moves the nick: make one "
                f"cover the other's rounded corner whole (reach past the arc's far end) or "
                f"make that corner square")
    if apex is not None:
        # a nick: the two sides meet at its floor, and taper apart from there; moving
        # one away parts them (W0504), moving it in moves the nick (issue 84): the
        # inner corner rounded by min_wall fills the narrow part and nothing else
        fill = (f"fill the nick where {names[0]} meets {names[-1]} by rounding that inner "
                f"corner: `Fillet(at=[({apex[0]:.4f}, {apex[1]:.4f})], radius={t:g})` in "
                f"`{s.name}` (only that corner; the rest of the outline is unchanged)")
        if length <= SEAM * t:
            return fill
        # a long seam of near parallel sides (run gv's dodecahedron net: a glue flap's side
        # along the next face's edge, 0.01 mm apart over 3.9 mm): the rounding fills it all,
        # joining the two there (a flap that no longer folds), and only 0.42 mm fits
        return (f"{fill}, which joins them along the slit's {length:.1f} mm; if they are to "
                f"stay apart there (a flap that folds, a tab), end one at least {t:g} mm "
                f"short of the other instead")
    # both figures rounded up to 0.01 mm: the gap 0.375 mm, "move one 0.12 mm away" (0.125
    # rounded to even) left 0.495 mm, warned again.  Overlapping by a hair ("more than
    # 0.25 mm towards", made 0.26) two round sides meet in a V-notch narrower than t over
    # more than t (the nick, warned again): they overlap by t
    return (f"make {names[0]} and {names[-1]} overlap by at least {t:g} mm (move one "
            f"{_up(w + t):.2f} mm towards the other) or open the gap to at least {t:g} mm "
            f"(move one {_up(t - w):.2f} mm away)")


def _up(x: float) -> float:
    """``x`` mm rounded up to 0.01 mm (a figure printed with two decimals that, moved by,
    reaches at least ``x``; 1e-8 mm of rounding noise is not a step up)."""
    return math.ceil(x * 100 - 1e-6) / 100
