"""A program's params beyond one compile: :mod:`.sweep` (``aidl check --sweep``: compiled across
their ranges), :mod:`.sweep_plan` (what a sweep sweeps), :mod:`.set_values` (a param's new value
written into the text). Imports the pipeline and below.
"""
