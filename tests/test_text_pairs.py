"""Laws of W0513's array passes (aidl_lang/output/checks/marks/text.py): the pairs of texts and
marks measured one by one are found for all pairs at once, and the passes must find every
pair that the one-by-one measures would (the one-by-one code then decides as before)."""
import math

import numpy as np
from hypothesis import given, settings, strategies as st

from aidl_lang.output.checks.marks.engravings import _seg_gap
from aidl_lang.output.checks.marks.text import (_Segments, _inside_by_pair, _length_inside,
                                          _near_pairs)
from aidl_lang.output.part.measure.nearby import box_pairs_between

coord = st.floats(-20, 20, allow_nan=False, width=32)
segment = st.tuples(coord, coord, coord, coord)
sets = st.lists(st.lists(segment, min_size=1, max_size=6), min_size=1, max_size=5)


def _arrays(sets):
    out = []
    for s in sets:
        S = np.array(s, dtype=float).reshape(-1, 2, 2)
        out.append((S[:, 0], S[:, 1]))
    return out


def _box(a, b):
    lo, hi = np.minimum(a, b).min(axis=0), np.maximum(a, b).max(axis=0)
    return [lo[0], lo[1], hi[0], hi[1]]


@settings(max_examples=60, deadline=None)
@given(sets, sets, st.lists(st.floats(0.3, 4), min_size=5, max_size=5))
def test_near_pairs_are_the_pairs_nearer_than_the_clearance(texts, marks, clear):
    T, M = _arrays(texts), _arrays(marks)
    strokes = [np.stack([a, b], axis=1) for a, b in T]
    clear = clear[:len(T)]
    bb = np.array([_box(*t) for t in T])
    mb = np.array([_box(*m) for m in M])
    pairs = box_pairs_between(bb, mb, max(clear))
    found = _near_pairs(strokes, pairs, bb, mb, clear, _Segments(M))
    for i in range(len(T)):
        for j in range(len(M)):
            gap = _seg_gap(*T[i], *M[j])[0]
            if gap < clear[i]:
                assert (i, j) in found, (i, j, gap, clear[i])
            elif gap > clear[i] + 1e-6:
                assert (i, j) not in found, (i, j, gap, clear[i])


@settings(max_examples=60, deadline=None)
@given(sets, sets, st.lists(st.floats(-math.pi, math.pi), min_size=5, max_size=5),
       st.lists(st.tuples(coord, coord, st.floats(0, 15), st.floats(0, 15)), min_size=5,
                max_size=5))
def test_lengths_inside_by_pair_are_each_pairs_clipped_length(texts, marks, rot, boxes):
    n = len(texts)
    rot = np.array(rot[:n])
    box = np.array([(u, v, u + w, v + h) for u, v, w, h in boxes[:n]])
    M = _arrays(marks)
    pairs = np.array([(i, j) for i in range(n) for j in range(len(M))], dtype=np.intp)
    (got,) = _inside_by_pair(pairs, rot, (box,), _Segments(M))
    for k, (i, j) in enumerate(pairs.tolist()):
        want = _length_inside(M[j], float(rot[i]), tuple(box[i]))
        assert abs(got[k] - want) <= 1e-9 * (1 + want), (i, j, got[k], want)
