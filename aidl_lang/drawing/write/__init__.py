"""Stage 4, writing: a :class:`~..model.Drawing` (its loops sorted into parts, holes and
engraving) in, the text of an editable AIDL program out (:mod:`.program`, the plain
``aidl import``: each loop written exactly, lines, arcs, circles and splines; the
:class:`~.program._Writer` that :mod:`..infer` writes its recognised shapes with)."""
