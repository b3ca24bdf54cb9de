"""``E0504`` at ``aidl check``: a program's ``kerf`` that one of its parts' cuts cannot be
offset by (a slot narrower than the beam, an arc of a radius under half of it), found as
``aidl render`` finds it (:func:`~...fabrication.layout.for_cutting`) and said at the hole
(:meth:`~...fabrication.layout.KerfError.diagnostic`).  Before, only `render` said it, and a
program that checked clean was refused when written (round eleven's list)."""
from __future__ import annotations


def check_kerf(d, sink, deadline=None) -> None:
    """E0504 for the first part of ``d`` (the booleans' :class:`Drawing`) whose cuts the
    program's ``kerf`` statements cannot offset; nothing without a kerf."""
    if not getattr(d, "kerf", None):
        return
    from ...fabrication.layout import KerfError, for_cutting
    from ...part.part import OutputError, build
    try:
        for_cutting(build(d, deadline=deadline), None, deadline)
    except KerfError as e:
        sink.add(e.diagnostic(d))
    except OutputError:
        pass                    # (a budget or memory limit: render says it, as before)
