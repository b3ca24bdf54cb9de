"""Holes and openings: :mod:`.openings` (W0501-W0503, W0507 between features, W0508, W0514),
:mod:`.voids` (W0515: an opening no hole cut), :mod:`.repeats` (W0512: copies that merge),
:mod:`.clearing` (W0508's fix), :mod:`.contact` (W0514's points of contact).  Imports
:mod:`..common` and the part stage.
"""
