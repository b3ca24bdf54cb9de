"""Holes and openings: :mod:`.openings` (W0501-W0503, W0507 between features, W0508, W0512, W0514,
W0515), :mod:`.clearing` (W0508's fix), :mod:`.contact` (W0514's points of contact). Imports
:mod:`..common` and the part stage.
"""
