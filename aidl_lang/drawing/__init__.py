"""Drawings brought in from other tools, in four stages, each a folder (docs/import.md,
"How an import works"):

1. :mod:`.read`: a DXF (ezdxf) or SVG (svgelements) file's bytes in, exact curves out;
2. :mod:`.chains`: curves in, closed loops and open paths out (the :mod:`.model`'s
   :class:`~.model.Drawing`, with its notes);
3. :mod:`.infer` (``aidl import --infer``): a Drawing in, the design it shows (shapes,
   patterns, features anchored to their part, params) out;
4. :mod:`.write`: a Drawing (or the inferred design) in, the text of an AIDL program out.

:mod:`.model` is the data they share.  Stages import only the ones below them:
infer > write > read > chains > model (pyproject.toml's contract).  docs/language.md
"Drawing2D" and docs/import.md."""
from .model import Drawing, DrawingError, Note
from .read import read_drawing

__all__ = ["Drawing", "DrawingError", "Note", "read_drawing"]
