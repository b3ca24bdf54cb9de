"""Stage 1 of ``aidl import`` and ``Drawing2D``, reading: a DXF (:mod:`.dxf`, ezdxf, with
:mod:`.dxf_spline` and :mod:`.dxf_text`) or SVG (:mod:`.svg`, svgelements) file's bytes in,
each shape's exact curves out (circles, arcs and ellipses through :mod:`.affine`'s exact
affine maps, splines, text), filtered by the :mod:`.roles` of its layers and colours and
joined by :mod:`..chains` into a :class:`~..model.Drawing` (:func:`.reader.read_drawing`)."""
from .reader import DrawingError, read_drawing

__all__ = ["DrawingError", "read_drawing"]
