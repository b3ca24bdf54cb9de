"""Engraving and text: :mod:`.engravings` (W0505, W0516, W0524), :mod:`.text` (W0513). Imports
:mod:`..common` and the part stage.
"""
