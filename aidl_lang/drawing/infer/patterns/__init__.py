"""Patterns among a part's holes (``aidl import --infer``): :mod:`.find` (bolt circles, rows,
grids, staggered and hex grids clipped to a field, ticks, outlines turned round a centre,
copies of a part), :mod:`.groups` (holes grouped as a maker means them: corner sets, board
sets), :mod:`.rings` (equal holes on rings about one centre, a bolt circle each) and
:mod:`.turns` (the loop turn that writes a given hole)."""
