"""Profiles (issue 93): an outline of lines at right angles (an L, T, U or Z bracket, a
stepped plate) read (:mod:`.read`), its faces placed by what they follow (:mod:`.faces`) and
written as a polygon of params with its fillets (:mod:`.write`)."""
