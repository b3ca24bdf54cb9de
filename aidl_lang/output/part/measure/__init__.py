"""Distances between outlines: :mod:`.nearby` (the spatial index), :mod:`.gaps` (exact clearances),
:mod:`.overlap` (exact shared area). Imports geometry only.
"""
