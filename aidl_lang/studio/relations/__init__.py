"""An imported drawing's inferred relations as the studio's sliders (issue 94), in three
rooms: :mod:`.drawn` (the entry, :func:`with_relations`: a round body with a bolt circle),
:mod:`.plates` (a rectangular plate's hole grid, window and corner holes) and :mod:`.syntax`
(the program syntax both read)."""
from .drawn import WALL, with_relations

__all__ = ["WALL", "with_relations"]
