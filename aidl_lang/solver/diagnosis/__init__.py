"""What a solve says about the model: :mod:`.diagnose` (conflict sets), :mod:`.freedom` (degrees of
freedom), :mod:`.redundancy` (W0401), :mod:`.sliding` (what can still move). Imports
:mod:`..core`.
"""
