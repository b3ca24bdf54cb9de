"""The exact edges of the output: :mod:`.exact` (which exact curve each polygon edge came from),
:mod:`.matching` (its first step: result edges matched to input chords over a grid),
:mod:`.shared` (the edges two pieces of one part share).  Imports geometry only.
"""
