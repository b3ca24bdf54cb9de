"""Drawings brought in from other tools: DXF (ezdxf) and SVG (svgelements) read as exact
curves (:mod:`.read`), and turned into an editable AIDL program (:mod:`.program`,
``aidl import``).  docs/language.md "Drawing2D" and docs/import.md."""
from .read import Drawing, DrawingError, Note, read_drawing

__all__ = ["Drawing", "DrawingError", "Note", "read_drawing"]
