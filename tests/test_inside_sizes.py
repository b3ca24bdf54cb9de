"""Inside sizes for every box generator (issue 95): with `outside=false` the numbers given are
the space a user fills.  The law, over every box-like template of the standard library and
generated sizes: in the assembled product (each part extruded by Manifold and placed by its
`Place`), a probe from the box's middle along +-x, +-y and +-z meets the inner faces exactly
that far apart, to 1e-9 mm (an open side: the box's own edge).  board_enclosure has no
`outside`: its inside is the board and the clearance all round, `depth` deep.
(~4 s CPU: 18 compiles.)"""
import manifold3d as mf
import pytest
from hypothesis import given, settings, strategies as st

import aidl_lang
from aidl_lang.output.fabrication.assembly import solids

CALLS = {
    "lid_box": ("boxes", "lid_box(length={L} mm, width={W} mm, height={H} mm, outside=false)"),
    "sliding_lid_box": ("boxes", "sliding_lid_box(length={L} mm, width={W} mm, height={H} mm, "
                                 "outside=false)"),
    "divider_tray": ("boxes", "divider_tray(length={L} mm, width={W} mm, height={H} mm, rows=1, "
                              "cols=1, outside=false)"),
    "hinged_box": ("boxes", "hinged_box(length={L} mm, width={W} mm, height={H} mm, outside=false)"),
    "drawer": ("boxes", "drawer(length={L} mm, depth={W} mm, height={H} mm, outside=false)"),
    "flex_box": ("boxes", "flex_box(length={L} mm, width={W} mm, height={H} mm, outside=false)"),
    "finger_box": ("joints", "finger_box(length={L} mm, depth={W} mm, height={H} mm, outside=false)"),
    "tool_holder": ("stands", "tool_holder(length={L} mm, depth={W} mm, height={H} mm, "
                              "outside=false)"),
    # the board L x W, 2 mm clearance all round; ports and vents away from the probes
    "board_enclosure": ("enclosures", "board_enclosure(width={L} mm, height={W} mm, depth={H} mm, "
                                      "holes=[], ports=[], vent=\"none\")"),
}
ONLY = {"drawer": ".carcass."}          # the drawer's carcass: the drawer itself stands inside
MORE = {"board_enclosure": (4.0, 4.0, 0.0)}


def _probe(u, c, axis, sign, far):
    """Where a probe from ``c`` along ``sign`` x ``axis`` first meets the solid ``u`` (None: it
    leaves the box)."""
    e = 1e-3
    size = [e, e, e]
    size[axis] = far
    at = [v - e / 2 for v in c]
    at[axis] = c[axis] if sign > 0 else c[axis] - far
    hit = u ^ mf.Manifold.cube(size).translate(at)
    if hit.is_empty():
        return None
    b = hit.bounding_box()
    return b[axis] if sign > 0 else b[axis + 3]


def inside(name, L, W, H):
    mod, call = CALLS[name]
    src = (f'import "std/{mod}.aidl"\nthickness 3 mm\n'
           f"assembly kit {{ b = {call.format(L=L, W=W, H=H)} }}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.errors]
    parts = [m for n, m in solids(r.output) if ONLY.get(name, ".") in n]
    u = mf.Manifold.batch_boolean(parts, mf.OpType.Add)
    b = u.bounding_box()
    c = [(b[k] + b[k + 3]) / 2 for k in range(3)]
    far = 4 * max(b[k + 3] - b[k] for k in range(3))
    out = []
    for axis in range(3):
        hi = _probe(u, c, axis, 1, far)
        lo = _probe(u, c, axis, -1, far)
        out.append((b[axis + 3] if hi is None else hi) - (b[axis] if lo is None else lo))
    return out


@pytest.mark.parametrize("name", list(CALLS))
@settings(max_examples=2, deadline=None)
@given(L=st.integers(70, 160), W=st.integers(60, 110), H=st.integers(30, 80),
       frac=st.sampled_from([0.0, 0.25, 0.5]))
def test_law_the_inside_is_the_size_given(name, L, W, H, frac):
    L, W, H = L + frac, W + frac, H + frac
    more = MORE.get(name, (0.0, 0.0, 0.0))
    assert inside(name, L, W, H) == pytest.approx([L + more[0], W + more[1], H + more[2]],
                                                  abs=1e-9)
