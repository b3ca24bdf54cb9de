"""The lengths a scaled copy of a shape keeps in its ``data`` (``Scaled``, ``Scale``: the
cloner of :mod:`.operations` calls :func:`scaled_data`; :mod:`.transforms` makes the copy)."""
from __future__ import annotations


# the lines `aidl docs Scale` (and the others) show in their example (reference.py); here, beside
# the scaling, so the reference reads them without loading the geometry's numpy
EXAMPLE_LINES = {
    "Scaled": "small = Scaled(h, 0.5, center=(20, 10))    # a 2 mm hole at (0, 0)",
    "Scale": "Scale(h, 1.5)    # the hole 6 mm across, about its own centre (-20, -10)",
    "Translated": "m = Translated(h, by=(30, 0))    # a copy at (10, -10)",
    "Translate": "Translate(h, (30, 20))    # the hole moved to (10, 10)",
    "Flip": "Flip(h, about=axis)    # the hole now at (20, -10), mirrored",
}


class ScaleRefused(ValueError):
    """A shape that cannot be scaled yet; the message is the diagnostic text."""


# data of a shape that are lengths (mm), scaled with it
_LENGTHS = ("corner_radius", "distance", "thickness", "width", "size", "weight", "bridge",
            "max_width")


def scaled_data(g, k: float) -> None:
    """Scale the lengths a copied shape ``g`` keeps in its ``data`` by ``k`` (in place)."""
    d = g.data
    if g.kind == "Drawing2D":
        raise ScaleRefused("a Drawing2D (an imported drawing) cannot be scaled yet: scale it "
                           "in the file it is read from")
    if g.kind == "Text" and d.get("along") is not None:
        raise ScaleRefused("Text along a curve cannot be scaled yet: give the Text its own "
                           "`size` and the curve its own size")
    for key in _LENGTHS:
        if isinstance(d.get(key), (int, float)) and not isinstance(d.get(key), bool):
            d[key] = d[key] * k
    if "corner_radii" in d:
        d["corner_radii"] = [r * k for r in d["corner_radii"]]
    if "dims" in d:
        d["dims"] = {n: v * k for n, v in d["dims"].items()}
    if "tip" in d:              # a Star's rounded tips: (the tip arc's centre from the star's
        dc, half = d["tip"]     # centre, mm; the arc's half sweep, radians: kept)
        d["tip"] = (dc * k, half)
    if "shrunk" in d:           # a Text shrunk to its max_width: (size asked, width at it)
        d["shrunk"] = tuple(v * k for v in d["shrunk"])
    if "extent" in d:
        d["extent"] = tuple(v * k for v in d["extent"])
    d.pop("box", None)
