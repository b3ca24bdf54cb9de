"""Stage 3, inference (``aidl import --infer``): a read :class:`~..model.Drawing` in, the
design it shows out, written with :mod:`..write`'s writer: :mod:`.shapes` recognises
each loop (circle, rectangle, rounded rectangle, slot, polygon), :mod:`.body` writes a
part's outline (:mod:`.profiles`: an L, T, U, Z bracket or a stepped plate),
:mod:`.patterns` finds the rows, grids and bolt circles among its holes, :mod:`.holes` the
holes makers draw, :mod:`.attachments` the features on a body's edge (notches, tabs),
:mod:`.mirror` mirrored pairs of parts, :mod:`.engrave` the texts and engravings;
:mod:`.params` names the sizes the program gives as params.  :func:`.infer.import_drawing`
is the entry."""
from .infer import import_drawing, to_program_inferred

__all__ = ["import_drawing", "to_program_inferred"]
