"""Fabrication: the exact output model in, what a machine or an assembler needs out.

In: :class:`~aidl_lang.output.part.part.Output` (exact outlines per part, mm).  Out: parts laid
out on sheets with the kerf offset (:mod:`.layout`), the cut order of every part (inner cuts
before outlines, :mod:`.toolpath`), the machine profiles (ranges and limits of lasers, routers,
plotters, :mod:`.machine`) and the assembled product (each part extruded and placed in 3D, the
fit check, :mod:`.assembly`); the writers turn these into G-code, HPGL, LightBurn, GLB, PNG.

Imports the part stage only (pyproject.toml's contract); the checks read the layout's boxes
and the assembly's fit (W0517/W0518), so fabrication sits below the checks."""
