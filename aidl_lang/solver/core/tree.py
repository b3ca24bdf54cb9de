"""The structure tree as the hierarchical solve (:mod:`.hierarchy`) reads it: its levels and
post-order, the rigid structures below a structure (they move only by their own frames), a
structure's construction geometry (helpers) and part shape (the first drawn closed shape),
the parts of an assembly that declares a hole, and "who moves" between siblings (issue 84:
:func:`_who_moves`, the references held and the ranks of those placed on them).  Pure
functions of :class:`~aidl_lang.geometry.core.model.Structure`: no solver state."""
from __future__ import annotations

from ...geometry.core.model import Model, Structure
from ...geometry.relations.bbox import collect


FEATURE_KINDS = ("hole", "cut", "drawing")   # placed on a part (engraved); the rest are parts


def _references(s: Structure) -> list:
    """The children of ``s`` that a constraint of ``s`` relates another child to and that no
    constraint of ``s`` moves ("who moves": between siblings the first-named moves to the
    second, the reference; a feature, a hole or a cut, moves to a part whatever the order).
    Read off each written constraint's arguments (``Constraint.args``): the child of ``s``
    each argument lies in, in the order written (an argument on ``s``'s own geometry, the
    part, is held anyway).  Held in the features stages
    (:meth:`.parts_first.PartsFirst._part_unknowns`) like ``s``'s own part; a child both moved
    by one constraint and the reference of another is not held (it moves to its own
    reference, the others follow it)."""
    return _who_moves(s)[0]


def _who_moves(s: Structure) -> tuple[list, list]:
    """(:func:`_references` of ``s``, the children of ``s`` that move to another in rank
    order: ``ranks[0]`` those placed on the references only, ``ranks[1]`` those placed on
    ``ranks[0]`` or a reference, ...; a child in a cycle of relations is in none)."""
    refs, ranks, _ = placed_on(s)
    return refs, ranks


def placed_on(s: Structure) -> tuple[list, list, dict]:
    """:func:`_who_moves` of ``s`` and, for each child that moves, the ids of the siblings it
    moves to (``{id(child): {id(sibling), ...}}``; empty when only ``s``'s own part is)."""
    if not s.children:
        return [], [], {}
    movers: dict[int, Structure] = {}
    refs: dict[int, Structure] = {}
    edges: dict[int, set] = {}          # id(mover) -> ids of its references
    for c in s.constraints:
        args = c.args
        if not args:
            continue
        groups: list = []           # s's children reached, in the order written
        lead = 0                    # how many of them the first argument reaches
        part = False
        for k, owners in enumerate(args):
            if k == 1:
                lead = len(groups)
            # by depth, then by path: a set of structures iterates in the order of their
            # addresses, so ties went one way or the other with what the process had
            # compiled before (a router template's solve: 6 Newton steps alone, 33 after
            # 143 other programs)
            for o in sorted(owners, key=lambda t: (_depth(t), t.path)):
                t = _child_toward(s, o)
                if t is None:
                    part = True
                elif t not in groups:
                    groups.append(t)
        if len(groups) < 1 + (not part):
            continue
        if c.__dict__.get("copy_rule"):
            # a pattern's copy goes with its original: never a reference held where written
            # (run z1's ring toss: labels `At` the copies held them, and the construction square
            # the original stands on moved instead); the original is not held for it (a
            # relation on a copy moves the original: `Concentric(hs[1].c, body)`)
            if len(groups) == 2:
                movers[id(groups[0])] = groups[0]
                edges.setdefault(id(groups[0]), set())
            continue
        solids = [t for t in groups if t.kind not in FEATURE_KINDS]
        if part and not (0 < lead < len(groups) and len(solids) in (0, len(groups))
                         and all(t.kind == "drawing" for t in groups[:lead])):
            # s's own part is the reference: every child moves (but a label placed between
            # features and the part moves alone, below)
            for t in groups:
                movers[id(t)] = t
                edges.setdefault(id(t), set())
            continue
        if 0 < lead < len(groups) and len(args) > 1 and len(solids) in (0, len(groups)):
            # the first argument's children move to the rest, each a reference (with s's own
            # part too: run ac's lucet, `mark.w.position.y == (hang.bb.top + head.bb.bottom)
            # / 2` moved the hanging hole 1.9 mm, said "stays where written"): an equation
            # of a label and two holes (run w's cup holder: `label.t.position.x == (mug.c.right.x
            # + notch.end.left.x) / 2` moved the mug hole 8.76 mm, the last-named alone held)
            for ref in groups[lead:]:
                refs[id(ref)] = ref
            for t in groups[:lead]:
                movers[id(t)] = t
                edges.setdefault(id(t), set()).update(id(r) for r in groups[lead:])
            continue
        ref = solids[-1] if solids and len(solids) < len(groups) else groups[-1]
        refs[id(ref)] = ref
        for t in groups:
            if t is not ref:
                movers[id(t)] = t
                edges.setdefault(id(t), set()).add(id(ref))
    placed = {k for k in refs if k not in movers}
    ranks: list = []
    todo = dict(movers)
    while todo:
        now = [k for k in todo if edges[k] <= placed]
        if not now:
            break                       # a cycle: left to the stages
        ranks.append([todo.pop(k) for k in now])
        placed.update(now)
    return [t for k, t in refs.items() if k not in movers], ranks, edges


def _shape_ranks(s: Structure, mine: set) -> tuple[list, list]:
    """Who moves between the shapes of ``s`` (issue 105): the first-named moves to the
    second, as between siblings (:func:`_who_moves`).  ``mine``: ``s``'s own unknowns (its
    shapes' free parameters).  Returns ``(references, ranks)``: the unknowns of the shapes
    a written constraint of ``s`` relates another shape to and that none moves (each a
    list), and ``ranks[k]`` the unknowns of the shapes placed on the references and on
    ranks below ``k`` (``ranks[0]``: on references only); a shape in a cycle of relations
    is in none.  A shape is one of ``s``'s listed geometries, those sharing an unknown
    (a Triangle through a Rectangle's corners) one, and a shape scaled in place one with its
    original; the arguments are read off each written
    constraint's parameters (``Constraint.reach``: ``At(ear.center, head.center)`` relates
    ear to head), so an equation's two sides are its arguments here too."""
    cons = [c for c in s.constraints if c.reach is not None]
    if not cons:
        return [], []
    parent: dict[int, int] = {}

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for g in s.geometry:                # one shape per geometry, joined where they share
        vs: set = set()
        _unknowns(g, vs)
        was = g.__dict__.get("in_place_of")
        if was is not None:             # Scale(ear, 1.5): the copy moves with its original
            _unknowns(was, vs)
        root = None
        for v in vs:
            parent.setdefault(v, v)
            r = find(v)
            if root is None:
                root = r
            elif r != root:
                parent[r] = root
    unit = {v: find(v) for v in parent}
    movers: set = set()
    refs: list = []
    edges: dict[int, set] = {}
    for c in cons:
        groups: list = []               # shapes reached, in the order written
        for r in c.reach:
            for u in sorted({unit[v] for v in r if v in unit}):
                if u not in groups:
                    groups.append(u)
        if len(groups) < 2:
            continue
        ref = groups[-1]
        if ref not in refs:
            refs.append(ref)
        for u in groups[:-1]:
            movers.add(u)
            edges.setdefault(u, set()).add(ref)
    # rank by rank (Kahn's order): a shape's rank is one more than its highest reference's
    level = {u: -1 for u in refs if u not in movers}
    waits = {u: len(edges[u]) for u in movers}
    users: dict[int, list] = {}
    for u in sorted(movers):
        for r in edges[u]:
            users.setdefault(r, []).append(u)
    ready = list(level)
    while ready:
        nxt = []
        for r in ready:
            for u in users.get(r, ()):
                waits[u] -= 1
                if not waits[u]:
                    level[u] = max(level[t] for t in edges[u]) + 1
                    nxt.append(u)
        ready = nxt
    ranks: list = [[] for _ in range(max(level.values(), default=-1) + 1)]
    for u in sorted(movers):
        if u in level:                      # (a shape in a cycle has none)
            ranks[level[u]].append(u)
    members: dict[int, list] = {}
    for v in sorted(unit):
        if v in mine:
            members.setdefault(unit[v], []).append(v)
    return ([members.get(u, []) for u in refs if u not in movers],
            [[v for u in rank for v in members.get(u, ())] for rank in ranks])


def _depth(t: Structure) -> int:
    n = 0
    while t.parent is not None:
        t, n = t.parent, n + 1
    return n


def _child_toward(s: Structure, o: Structure):
    """The child of ``s`` whose subtree holds ``o`` (None: ``o`` is ``s`` or not below it)."""
    while o is not None and o.parent is not s:
        o = o.parent
    return o


def _helpers(s: Structure) -> list:
    """``s``'s own construction geometry (``construction=true``): solved, never drawn."""
    return [g for g in s.geometry if g.construction]


def _held_helpers(s: Structure, helpers: list) -> set:
    """The unknowns of those of ``helpers`` (``s``'s construction geometry) that the
    features stages hold like the part (issue 111): a helper is a reference when a written
    constraint of ``s`` names a child's geometry first and the helper after it
    (`Midpoint(tab.r.bottom.midpoint, axis)`: the tab moves to the axis, as the first-named
    does; the axis, moved 4.6 mm of the way, left a tail drawn at its coordinates behind),
    and nothing else of ``s`` names it: a helper also related to the part or to another
    shape, or named first, moves as before (a bolt square placed on its plate)."""
    if not helpers:
        return set()
    units = []
    for g in helpers:
        vs: set = set()
        _unknowns(g, vs)
        units.append(vs)
    ref = [False] * len(helpers)
    other = [False] * len(helpers)
    for c in s.constraints:
        ar = c.__dict__.get("arg_reach")
        hit = [i for i, vs in enumerate(units)
               if ar is not None and any(r & vs for r in ar)
               or c.reach is not None and any(r & vs for r in c.reach)]
        if not hit and c.reach is None and c.deferred and c.args:
            # a relation of boxes (`CenterInside(words, band)`: no reach of its own): the
            # helpers whose box it reads, named after a child first (run t's photo-booth
            # frame: the band moved 3.5e-5 mm to the words, then 12.5 mm when they were off)
            read = {id(t.target) for eq in c.deferred for t in collect(eq.expr, [])}
            after = s not in c.args[0] and any(s in a for a in c.args[1:])
            for i, g in enumerate(helpers):
                if id(g) in read:
                    (ref if after else other)[i] = True
            continue
        if not hit:
            continue
        if ar is None or c.args is None or len(ar) != len(c.args):
            for i in hit:
                other[i] = True
            continue
        first = c.args[0]
        child_first = bool(first) and s not in first and not (ar[0] & set().union(*units))
        for i in hit:
            if child_first and not any(r & units[i] for r in ar[:1]):
                ref[i] = True
            else:
                other[i] = True
    out: set = set()
    for i, vs in enumerate(units):
        if ref[i] and not other[i]:
            out |= vs
    return out


def _unknowns(g, out: set) -> None:
    """Add the parameter indices of geometry ``g`` (its points, scalars and parts) to
    ``out``."""
    for p in g.points.values():
        out.add(p.ix)
        out.add(p.iy)
    for sc in g.scalars.values():
        out.add(sc.index)
    for part in g.parts.values():
        if hasattr(part, "points"):
            _unknowns(part, out)


def _part_shape(s: Structure):
    """A solid's part among its own shapes: the first drawn closed one (not construction
    geometry, not a copy made by a pattern), or None."""
    if s.kind != "solid":
        return None
    for g in s.geometry:
        if g.closed and not g.construction and g.pattern_original is None \
                and g.kind not in ("Text", "Point"):
            return g
    return None


def _cut_parts(model: Model) -> dict[int, list]:
    """``id(assembly)`` -> its children that are parts (not holes), for each assembly that
    declares a hole: a hole declared in an assembly is placed on a part of it (and cut into
    it with ``CutInto(lid_hole, box.lid)``, where both meet; without it, ``W0109``, whose
    fix writes it, so that the fix moves nothing), so those children are held like a
    structure's own geometry (:meth:`.parts_first.PartsFirst._part_unknowns`)."""
    out: dict[int, list] = {}
    for t in model.structures:
        a = t.parent
        if t.kind in ("hole", "cut") and a is not None and a.kind == "assembly" \
                and id(a) not in out:
            out[id(a)] = [c for c in a.children.values() if c.kind not in ("hole", "cut")]
    return out


def _rigid_below(s: Structure) -> tuple[set, set]:
    """(ids of structures whose own parameters, ids of those whose frames) the solve of ``s``
    may not free: every rigid structure strictly below ``s`` keeps its own parameters and
    its whole subtree (only its own frame moves); ``s``'s own rigidity does not concern its
    own solve."""
    no_own: set = set()
    no_frame: set = set()
    todo = list(s.children.values())
    while todo:
        t = todo.pop()
        if getattr(t, "rigid", False):
            inner = [t]
            while inner:
                u = inner.pop()
                no_own.add(id(u))
                if u is not t:
                    no_frame.add(id(u))
                inner += u.children.values()
        else:
            todo += t.children.values()
    return no_own, no_frame


def _post_order(s: Structure):
    for c in s.children.values():
        yield from _post_order(c)
    yield s


def _levels(s: Structure) -> list[list[Structure]]:
    out = [[s]]
    while True:
        nxt = [c for t in out[-1] for c in t.children.values()]
        if not nxt:
            return out
        out.append(nxt)
