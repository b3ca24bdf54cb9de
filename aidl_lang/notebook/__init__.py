"""AIDL in Jupyter notebooks: a form of a program's params that redraws its drawing.

>>> from aidl_lang.notebook import form
>>> f = form("examples/mounting_plate.aidl")     # doctest: +SKIP
>>> f                                             # doctest: +SKIP  (sliders over the drawing)

:func:`form` reads a program (its text, or a path to a ``.aidl`` file), builds one
`ipywidgets <https://ipywidgets.readthedocs.io>`_ control per top-level ``param`` — a slider
for a length (mm), an angle (degrees) or a number (an integer slider for a count), a checkbox
for a boolean, a text box for a string — with the ranges and steps ``aidl serve`` and the
studio give their sliders (:func:`aidl_lang.serve.params.declared_params`: the file's
``min=``/``max=``/``step=``, else a span around the value), and under them the drawing, redrawn
(debounced) whenever a control changes.  A program with errors shows its located errors in
place of the drawing.  The compiled result itself (:class:`aidl_lang.Result`) shows its
drawing when it is a cell's value; see docs/notebook.md.

ipywidgets is the optional ``notebook`` extra (``pip install 'aidl-lang[notebook]'``); this
module imports it only when :func:`form` is called, and says which extra to install when it is
missing.
"""
from __future__ import annotations

from .controls import NOTEBOOK_EXTRA, Form, FormError, form

__all__ = ["form", "Form", "FormError", "NOTEBOOK_EXTRA"]
