"""The material left between cuts: :mod:`.walls` (W0507: a wall thinner than the minimum, by
an opening of the part), :mod:`.necks` (W0507: two members joined over a neck), :mod:`.slits`
(W0519: a slit of empty space), :mod:`.nicks` (W0519's fix), :mod:`.through` (W0522 and the
webs between through-cuts), :mod:`.toolpath_walls` (what a bit or a kerf leaves).  Imports
:mod:`..marks`, :mod:`..common` and the stages below.
"""
