"""Drawings brought in from other tools: DXF (ezdxf) and SVG (svgelements) read as exact
curves (:func:`~.read.read_drawing`: :mod:`.dxf`, :mod:`.svg`, joined by :mod:`.chain` into
the :mod:`.model`'s outlines and paths, with the :mod:`.roles` of their layers and colours),
and turned into an editable AIDL program (:mod:`.program`, ``aidl import``).
docs/language.md "Drawing2D" and docs/import.md."""
from .model import Drawing, DrawingError, Note
from .read import read_drawing

__all__ = ["Drawing", "DrawingError", "Note", "read_drawing"]
