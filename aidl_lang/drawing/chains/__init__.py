"""Stage 2, chains: the curves a reader found in, closed loops and open paths out (the
:class:`~..model.Drawing`'s outlines and paths).  :mod:`.chain` joins pieces end to end
within the join tolerance and closes small gaps; :mod:`.snap` takes Bézier runs that are
circles or arcs as the true curves (``--snap``); :mod:`.hole_cuts` cuts holes drawn
overlapping at their exact crossings; :mod:`.notches` tells a loop across a part's edge
(a notch) from a part of its own."""
