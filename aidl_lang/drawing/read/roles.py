"""The role of each shape of a drawing: ``cut=``, ``engrave=``, ``ignore=`` (layer names,
colours, ACI numbers) and the preset ``roles="laser"`` (Boxes.py's colours) in, a function
``(layer names, rgb, aci) -> "cut" | "engrave" | "ignore"`` out (:func:`_role_of`), which
:func:`~.read.read_drawing` hands the readers as their filter.  Colours are CSS colours
(svgelements) or AutoCAD colour indices (ezdxf's table)."""
from __future__ import annotations

from ..model import DrawingError


# roles="laser": the colours Boxes.py (boxes/Color.py: OUTER_CUT black, INNER_CUT blue,
# ANNOTATIONS red, ETCHING green, ETCHING_DEEP cyan) and the laser programs that read its
# SVGs use (docs/import.md)
ROLE_PRESETS = {"laser": {"cut": ["#000000", "#0000ff"], "engrave": ["#00ff00", "#00ffff"],
                          "ignore": ["#ff0000"]}}
ROLES = ("cut", "engrave", "ignore")


def _colour(v):
    """``v`` (a CSS colour name, ``#rgb``/``#rrggbb``, ``rgb(...)``; or an ACI number) as
    ``("rgb", (r, g, b))`` or ``("aci", n)``; None when ``v`` is no colour (a layer name)."""
    if isinstance(v, bool):
        return None
    if isinstance(v, (int, float)) and float(v).is_integer():
        return ("aci", int(v))
    if not isinstance(v, str):
        return None
    import re
    import svgelements as S
    t = v.strip().lower()
    if re.fullmatch(r"#[0-9a-f]{3}|#[0-9a-f]{6}", t) or re.fullmatch(r"rgb\(.*\)", t) or \
            t == "black" or S.Color.parse_color_lookup(t) != 255:
        c = S.Color(t)
        return ("rgb", (c.red, c.green, c.blue))
    return None


def _role_of(cut, engrave, ignore, roles, where: str = ""):
    """The role of a shape from ``cut=``, ``engrave=``, ``ignore=`` (each a layer name, a
    colour or an ACI number, or a list of them) and the preset ``roles=``: a function
    ``(layer names, rgb, aci) -> "cut" | "engrave" | "ignore"``, or None when none is
    given (everything is cut, as before).  A shape no role names is cut when ``cut=`` is not
    given, else ignored.  Raises :class:`DrawingError` (``E0130``) for an unknown preset."""
    given = {"cut": cut, "engrave": engrave, "ignore": ignore}
    if roles is not None:
        if not isinstance(roles, str) or roles.lower() not in ROLE_PRESETS:
            raise DrawingError("E0130", f"unknown roles preset {roles!r}",
                               "roles=\"laser\" (Boxes.py's colours: black and blue cut, "
                               "green engrave, red annotations ignored), or give cut=, "
                               "engrave= and ignore= by layer or colour")
        for k, v in ROLE_PRESETS[roles.lower()].items():
            if given[k] is None:
                given[k] = v
    if all(v is None for v in given.values()):
        return None
    sel = {}
    for k, v in given.items():
        vs = [] if v is None else [v] if isinstance(v, (str, int, float)) else list(v)
        sel[k] = [(str(x).lower(), _colour(x)) for x in vs]

    def close(a, b) -> bool:
        return a is not None and b is not None and all(abs(x - y) <= 2 for x, y in zip(a, b))

    def role(layers, rgb, aci) -> str:
        low = [n.lower() for n in layers]
        for k in ("ignore", "engrave", "cut"):
            for text, col in sel[k]:
                if text in low:
                    return k
                if col is not None and col[0] == "aci" and aci is not None and col[1] == aci:
                    return k
                if col is not None and col[0] == "rgb" and close(col[1], rgb):
                    return k
                if col is not None and col[0] == "aci" and aci is None and rgb is not None:
                    from ezdxf.colors import aci2rgb
                    if close(tuple(aci2rgb(col[1])) if col[1] not in (0, 7) else (0, 0, 0),
                             rgb):
                        return k
        return "cut" if given["cut"] is None else "ignore"
    return role


def _colour_name(rgb) -> str:
    if rgb is None:
        return "no colour"
    names = {(0, 0, 0): "black", (255, 0, 0): "red", (0, 0, 255): "blue", (0, 255, 0): "green",
             (255, 255, 255): "white"}
    return names.get(tuple(rgb), "#%02x%02x%02x" % tuple(rgb))
