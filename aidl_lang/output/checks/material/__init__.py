"""The material left between cuts: :mod:`.walls` (W0507, W0519), :mod:`.nicks` (W0519's fix),
:mod:`.through` (W0522), :mod:`.toolpath_walls` (what a bit or a kerf leaves). Imports
:mod:`..marks`, :mod:`..common` and the stages below.
"""
