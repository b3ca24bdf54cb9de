# AIDL standard library: finger (box) joints for laser-cut panels.
#   import "std/joints.aidl"
# docs/stdlib.md ("Finger joints") draws the conventions. Sizes are nominal:
# for the laser's kerf write `kerf 0.15 mm` (docs/language.md 2.1b), which
# widens every finger and narrows every slot by the kerf, so joints fit as
# drawn.

# A box panel with finger joints: `width` x `height` (outer size, centered at
# (cx, cy)) for material `thickness`. Each edge is one of "fingers", "slots"
# or "flat". Along an edge, the part between the two corner squares (thickness x
# thickness) is cut into an odd number of equal segments, each at least
# `finger` wide (the largest odd count that fits, but at least 3 as long as
# they stay `thickness` wide); "fingers" keeps the even
# ones (the first, the third, ...) and cuts the others `thickness` deep,
# "slots" is its complement, so the "fingers" edge of one panel mates the
# "slots" edge of another of the same length. "flat" keeps the whole edge. A
# corner square is kept unless one of its edges is "slots".
# Members: `outline` (construction rectangle of the outer size), `core` (the
# panel inside its joints, two thicknesses smaller each way: engraving there
# is clear of them, `Inside(label, core)`).
# Anchor: (cx, cy) is the centre of `outline`.
def finger_panel(width=100 mm, height=60 mm, thickness=3 mm, finger=10 mm,
                 bottom="fingers", right="fingers", top="fingers", left="fingers",
                 cx=0 mm, cy=0 mm) -> solid {
    t = thickness
    kinds = [bottom, right, top, left]
    for kind in kinds {
        assert (1 if kind == "fingers" or kind == "slots" or kind == "flat" else 0) == 1, "an edge is \"fingers\", \"slots\" or \"flat\""
    }
    assert thickness > 0 mm, "the thickness is more than 0"
    assert width > 2 * t and height > 2 * t, "a panel must be larger than twice the thickness"
    outline = Rectangle(center=(cx, cy), width=width, height=height, construction=true)
    core = Rectangle(center=(cx, cy), width=width - 2 * t, height=height - 2 * t)
    Fixed(core.center)
    core.center == outline.center
    # along x and along y: the run between the corner squares and its count of segments,
    # the largest odd count at least `finger` wide; at least 3 (narrower fingers) while
    # they stay `thickness` wide, so that the joint interlocks
    runs = [width - 2 * t, height - 2 * t]
    qs = [floor(r / finger) for r in runs]
    odds = [q if q % 2 == 1 else q - 1 for q in qs]
    counts = [odds[k] if odds[k] >= 3 else (3 if runs[k] >= 3 * t else 1) for k in range(2)]
    # the tabs of each edge (bottom, right, top, left), reaching t/2 into the core, at most
    # half across it (a core thinner than t: the far edge's tabs filled this edge's slots)
    reach = [0.5 * min(t, runs[1]), 0.5 * min(t, runs[0])]
    for e in range(4) {
        kind = kinds[e]
        run = runs[e % 2]
        n = 1 if kind == "flat" else counts[e % 2]
        w = run / n
        for i in range(n) {
            if kind == "flat" or (kind == "fingers") == (i % 2 == 0) {
                s = t + (i + 0.5) * w
                deep = t + reach[e % 2]
                side_x = cx + width / 2 - deep / 2 if e == 1 else cx - width / 2 + deep / 2
                side_y = cy - height / 2 + deep / 2 if e == 0 else cy + height / 2 - deep / 2
                tx = cx - width / 2 + s if e % 2 == 0 else side_x
                ty = cy - height / 2 + s if e % 2 == 1 else side_y
                tab = Rectangle(center=(tx, ty), width=w if e % 2 == 0 else deep,
                                height=w if e % 2 == 1 else deep)
                Fixed(tab.center)
            }
        }
    }
    # corner squares (bottom-left, bottom-right, top-right, top-left): t x t, reaching into
    # the core and along each edge by t/2 but never past half the edge's first segment (a
    # finger there, as the corner is kept only between "fingers" and "flat" edges): with
    # fingers narrower than t/2 a full 1.5 t square filled part of the next slot
    ex = 0.5 * min(t, runs[0] / counts[0])
    ey = 0.5 * min(t, runs[1] / counts[1])
    for c in range(4) {
        if kinds[c] != "slots" and kinds[(c + 3) % 4] != "slots" {
            sx = -1 if c == 0 or c == 3 else 1
            sy = -1 if c < 2 else 1
            corner = Rectangle(center=(cx + sx * (width / 2 - (t + ex) / 2), cy + sy * (height / 2 - (t + ey) / 2)),
                               width=t + ex, height=t + ey)
            Fixed(corner.center)
        }
    }
}

# A finger-jointed box as six flat panels (`closed=false`: open-top, no lid).
# `length` x `depth` x `height` is its outer size when `outside=true`, else the
# space inside (the outer size is then larger by two thicknesses each way, one
# in height when open), from material `thickness`; the panels are laid out
# flat (a net, `gap` apart) around the bottom centered at (cx, cy): front
# below it, back above it, the lid above the back, left and right beside it.
# The front and back lie upright (their top edge at +y: `front.bb.bottom` is
# the box's bottom edge); the left and right lie on their side, their top edge
# outward (the left's at -x, the right's at +x), so a side is `height` wide in
# x and `depth` tall in y, its +y towards the box's front. The front and back have fingers on every edge and keep their corners; the
# bottom and lid have slots along the front and back and fingers at the
# sides; the sides have slots all round. Members: `bottom`, `front`, `back`,
# `left`, `right`, `lid` (each a finger_panel). Each panel is placed in 3D
# (`Place`): assembled (`aidl render --assembled`), the box stands on z = 0,
# centered on x = y = 0, its fingers in their slots; the walls' and the lid's
# top faces (an engraving as drawn in the net) look out, the bottom's in; the
# back reads from behind (its +x is the box's left).
# Anchor: (cx, cy) is the centre of `bottom`.
def finger_box(length=120 mm, depth=80 mm, height=50 mm, thickness=3 mm,
               finger=10 mm, closed=true, gap=5 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    # the outer sizes
    L = length if outside else length + 2 * thickness
    D = depth if outside else depth + 2 * thickness
    H = height if outside else height + (2 if closed else 1) * thickness
    assert thickness > 0 mm, "the thickness is more than 0"
    assert L > 2 * thickness and D > 2 * thickness and H > 2 * thickness, "the box must be more than two thicknesses long, deep and tall (outside)"
    open = "slots" if closed else "flat"
    bottom = finger_panel(width=L, height=D, thickness=thickness, finger=finger,
                          bottom="slots", right="fingers", top="slots", left="fingers", cx=cx, cy=cy)
    front = finger_panel(width=L, height=H, thickness=thickness, finger=finger,
                         top="fingers" if closed else "flat", cx=cx, cy=cy - (D + H) / 2 - gap)
    back = finger_panel(width=L, height=H, thickness=thickness, finger=finger,
                        top="fingers" if closed else "flat", cx=cx, cy=cy + (D + H) / 2 + gap)
    left = finger_panel(width=H, height=D, thickness=thickness, finger=finger,
                        bottom="slots", right="slots", top="slots", left=open,
                        cx=cx - (L + H) / 2 - gap, cy=cy)
    right = finger_panel(width=H, height=D, thickness=thickness, finger=finger,
                         bottom="slots", right=open, top="slots", left="slots",
                         cx=cx + (L + H) / 2 + gap, cy=cy)
    bottom.outline.center == (cx, cy)
    front.outline.center == (cx, cy - (D + H) / 2 - gap)
    back.outline.center == (cx, cy + (D + H) / 2 + gap)
    left.outline.center == (cx - (L + H) / 2 - gap, cy)
    right.outline.center == (cx + (L + H) / 2 + gap, cy)
    if closed {
        lid = finger_panel(width=L, height=D, thickness=thickness, finger=finger,
                           bottom="slots", right="fingers", top="slots", left="fingers",
                           cx=cx, cy=cy + D + H + 2 * gap)
        lid.outline.center == (cx, cy + D + H + 2 * gap)
        Place(lid, position=(-cx, -(cy + D + H + 2 * gap), H - thickness))
    }
    # assembled: each panel folded up from the net about its edge on the bottom
    Place(bottom, position=(-cx, -cy, 0 mm))
    Place(front, rotation=(90 deg, 0, 0),
          position=(-cx, thickness - D / 2, H / 2 - (cy - (D + H) / 2 - gap)))
    # each wall's top face (its engraving, as drawn in the net) looks out of the box
    Place(back, position=(cx, D / 2 - thickness, H / 2 - (cy + (D + H) / 2 + gap)),
          face="back", up="up")
    Place(left, position=(thickness - L / 2, cy, cx - (L + H) / 2 - gap + H / 2),
          face="left", up="front")
    Place(right, position=(L / 2 - thickness, cy, H / 2 - (cx + (L + H) / 2 + gap)),
          face="right", up="front")
}

# ---------------------------------------------------------------------------
# Joints between any two panels. Each is a `hole` cut into a panel, placed by
# (cx, cy) on the panel's edge and `rotation`: at rotation 0 the edge runs
# along x through (cx, cy) and the panel lies below it (toward -y), as for
# `t_slot` (a `dovetail`'s line through (cx, cy) is where its tails start, the
# socket panel's edge: the socket panel lies above it, the tail panel reaches
# `depth` across it). Each says its point in its `Anchor:` line. A cut that
# opens an edge runs 1 mm past it, so it opens cleanly: that run is drawn as
# the member `overrun` (`overrun=true`), which counts in no box, so the box a
# relation reads is the cut within the part (`AlignTop(slot, panel)` of a
# 30 mm `cross_halving` cuts 30 mm deep).

import "std/fasteners.aidl"

# A cross-halving slot: panels slotted halfway into each other crosswise.
# From the mouth at (cx, cy) on the edge it runs `depth` mm into the panel,
# `thickness` + `clearance` wide; cut one into each panel, the two depths
# adding up to the overlap. Members: `cut` (within the panel: the box a
# relation reads), `overrun` (the cut run 1 mm past the edge: drawn, in no box).
# Anchor: (cx, cy) is the middle of its mouth on the edge; rotation 0: the slot runs toward -y.
def cross_halving(depth=20 mm, thickness=3 mm, clearance=0 mm, rotation=0 deg,
                  cx=0 mm, cy=0 mm) -> hole {
    assert depth > 0 mm and thickness + clearance > 0 mm, "the slot needs a depth and a width"
    v = -depth / 2
    cut = Rectangle(center=(cx - v * sin(rotation), cy + v * cos(rotation)),
                    width=thickness + clearance, height=depth, rotation=rotation)
    vo = (1 mm - depth) / 2
    overrun = Rectangle(center=(cx - vo * sin(rotation), cy + vo * cos(rotation)),
                        width=thickness + clearance, height=depth + 1 mm, rotation=rotation,
                        overrun=true)
    Fixed(cut)
    Fixed(overrun)
    Fixed(self)
}

# A finger joint along any panel edge, starting with a "tab" or "gap".
# The edge, `length` long and centred on (cx, cy), is cut into the largest odd
# number of equal segments at least `finger` wide (at least 3 while they stay
# `thickness` wide); every second one, from the first when `start` is "gap",
# is cut `thickness` deep, so a "tab" edge mates a "gap" edge of the same
# length at a corner. Members: `gap` (a list, one shape per gap, within the
# panel: `gap[0]`; the joint's box, `j.bb`, is theirs), `overrun` (each run
# 1 mm past the edges: drawn, in no box; an end gap runs 1 mm on past the
# joint's end along the edge, so an edge that goes on beyond the joint is notched
# 1 mm there: start with "tab" at such an end).
# Anchor: (cx, cy) is the middle of the edge; rotation 0: the edge along x, the cuts toward -y.
def finger_edge(length=100 mm, thickness=3 mm, finger=10 mm, start="tab", rotation=0 deg,
                cx=0 mm, cy=0 mm) -> hole {
    assert (1 if start == "tab" or start == "gap" else 0) == 1, "start is \"tab\" or \"gap\""
    assert thickness > 0 mm and length > thickness, "the edge must be longer than the thickness, which is more than 0"
    t = thickness
    q = floor(length / finger)
    odd = q if q % 2 == 1 else q - 1
    n = odd if odd >= 3 else (3 if length >= 3 * t else 1)
    w = length / n
    c = cos(rotation)
    s = sin(rotation)
    for i in range(n) {
        if (start == "gap") == (i % 2 == 0) {
            lo = -length / 2 + i * w
            hi = -length / 2 + (i + 1) * w
            u = (lo + hi) / 2
            v = -t / 2
            gap = Rectangle(center=(cx + u * c - v * s, cy + u * s + v * c), width=hi - lo,
                            height=t, rotation=rotation)
            Fixed(gap)
            lo = lo - (1 mm if i == 0 else 0 mm)
            hi = hi + (1 mm if i == n - 1 else 0 mm)
            u = (lo + hi) / 2
            v = (1 mm - t) / 2
            overrun = Rectangle(center=(cx + u * c - v * s, cy + u * s + v * c), width=hi - lo,
                                height=t + 1 mm, rotation=rotation, overrun=true)
            Fixed(overrun)
        }
    }
    Fixed(self)
}

# A tab-and-slot joint: glued (`screw=0`: tabs in closed slots, a mortise, never at an edge) or with captive nuts (T-slots).
# `part` "tab" cuts the edge of one panel down to `tabs` tabs `tab` wide
# (`thickness` long, spread evenly over `length`; the panel's edge on the line through
# (cx, cy), the tabs' tips, the panel below it at rotation 0 (above it: 180 deg): the gaps are cut
# `thickness` into it; give `length` the whole edge: the end gaps run 1 mm on
# past `length` along the edge, to cut cleanly through a sloping side, so an edge
# that goes on beyond the joint is notched 1 mm there) with a `t_slot` for an M`screw`
# screw and its nut between each two; "slot" cuts the mate: a slot
# `tab` + `clearance` by `thickness` + `clearance` for each tab and a medium
# clearance hole for each screw, centred on the line through (cx, cy) where the
# tab panel's middle stands. Screws up to `thickness` + 4 x `screw` mm long;
# `screw=0` leaves them out (a glued or pressed joint); `tabs=1`: one tab, a
# tenon in its mortise, has no screw (they go between tabs). Of two materials,
# `thickness` is the other panel's in each half: the slotted panel's for "tab"
# (how far the tabs stand out), the tab panel's for "slot" (the slot's width).
# Members: each a list; of part "tab", `gap` (within the panel; one more than
# tabs), `overrun` (each gap run 1 mm past the edges: drawn, in no box) and
# `nut` (one between each two tabs); of part "slot", `slot` (one per tab, even
# with `tabs=1`: `j.slot[0].bb`) and `bolt` (one between each two tabs). The
# whole joint's box is `j.bb` (a tab part's: its gaps' and, with a screw, its
# T-slots', which reach 4 x `screw` + `thickness` in: the gaps alone,
# `j.gap[0].bb`). Tab (and slot) i, from 0, is centred (i + 0.5) x `length` /
# `tabs` along the edge from its start, `length` / 2 before (cx, cy) (rotation
# 0: at x = cx - length / 2 + (i + 0.5) x length / tabs), so `tab` is less
# than `length` / `tabs`, even for one tab. A slotted panel
# needs material round each slot: a slot at its panel's edge opens as a
# notch (W0530). Into a template's panel, `CutInto(j, box.lid)`.
# Anchor: (cx, cy) is the middle of the edge (part "slot": of the slots); rotation 0: the edge along x, the panel toward -y.
def tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=10 mm, screw=3,
                 clearance=0 mm, rotation=0 deg, cx=0 mm, cy=0 mm) -> hole {
    assert (1 if part == "tab" or part == "slot" else 0) == 1, "part is \"tab\" or \"slot\""
    assert tabs >= 1, "at least 1 tab"
    assert tab < length / tabs, "each tab narrower than length / tabs"
    t = thickness
    p = length / tabs
    c = cos(rotation)
    s = sin(rotation)
    size = screw * 1 mm
    if part == "tab" {
        for i in range(tabs + 1) {
            lo = -length / 2 if i == 0 else -length / 2 + (i - 0.5) * p + tab / 2
            hi = length / 2 if i == tabs else -length / 2 + (i + 0.5) * p - tab / 2
            u = (lo + hi) / 2
            v = -t / 2
            gap = Rectangle(center=(cx + u * c - v * s, cy + u * s + v * c), width=hi - lo,
                            height=t, rotation=rotation)
            Fixed(gap)
            lo = lo - (1 mm if i == 0 else 0 mm)
            hi = hi + (1 mm if i == tabs else 0 mm)
            u = (lo + hi) / 2
            v = (1 mm - t) / 2
            overrun = Rectangle(center=(cx + u * c - v * s, cy + u * s + v * c), width=hi - lo,
                                height=t + 1 mm, rotation=rotation, overrun=true)
            Fixed(overrun)
        }
        for k in range(1, tabs if screw > 0 else 1) {
            u = -length / 2 + k * p
            nut = t_slot(size=screw, length=4 * size, nut_depth=2 * size, rotation=rotation,
                         cx=cx + u * c + t * s, cy=cy + u * s - t * c)
            Fixed(nut)
        }
    } else {
        for i in range(tabs) {
            u = -length / 2 + (i + 0.5) * p
            slot = Rectangle(center=(cx + u * c, cy + u * s), width=tab + clearance,
                             height=t + clearance, rotation=rotation)
            Fixed(slot)
        }
        for k in range(1, tabs if screw > 0 else 1) {
            u = -length / 2 + k * p
            bolt = clearance_hole(size=screw, fit="medium", cx=cx + u * c, cy=cy + u * s)
            Fixed(bolt)
        }
    }
    Fixed(self)
}

# A flat sliding dovetail locking two panels edge to edge.
# Over a band `depth` deep along the edge (from the line through (cx, cy) to
# `depth` beyond it, `length` long), `part` "tail" leaves `tails` tails that
# widen at `angle` toward their tips (the tail panel reaches across the band);
# "socket" cuts those tails, `clearance` wider, out of the mate (which starts
# at the line). Give `length` the whole edge: beyond it nothing is cut, so the
# tail panel's band and the mate overlap there (a 100 mm joint on a
# 160 mm edge, the tray could not drop in). Members: `cut` (a list, one shape
# per gap or socket, within the panel: `cut[0]`; the joint's box, `j.bb`, is
# theirs), `overrun` (each cut run 1 mm past the edges: drawn, in no box).
# Anchor: (cx, cy) is the middle of the tails' roots (the socket panel's edge); rotation 0: the tails toward +y.
def dovetail(part="tail", length=60 mm, depth=10 mm, tails=2, angle=10 deg, clearance=0 mm,
             rotation=0 deg, cx=0 mm, cy=0 mm) -> hole {
    assert (1 if part == "tail" or part == "socket" else 0) == 1, "part is \"tail\" or \"socket\""
    assert tails >= 1 and depth > 0 mm, "at least 1 tail and some depth"
    p = length / tails
    d = depth
    k = tan(angle)
    assert p / 4 - (d / 2 + 1 mm) * k > 0 mm and p / 4 - d / 2 * k > 0 mm, "the tails are too steep for their pitch"
    c = cos(rotation)
    s = sin(rotation)
    if part == "tail" {
        # the sockets between the tails (half ones at both ends), open past the edge
        for i in range(tails + 1) {
            m = -length / 2 + i * p
            a0 = p / 4 + d / 2 * k  # half width at the line (v = 0)
            a1 = p / 4 - d / 2 * k  # half width at the tips (v = d)
            l0 = -length / 2 if i == 0 else m - a0
            l1 = -length / 2 if i == 0 else m - a1
            r0 = length / 2 if i == tails else m + a0
            r1 = length / 2 if i == tails else m + a1
            uv = [(l0, 0 mm), (r0, 0 mm), (r1, d), (l1, d)]
            cut = Polygon([(cx + q[0] * c - q[1] * s, cy + q[0] * s + q[1] * c) for q in uv])
            Fixed(cut)
            e0 = 1 mm if i == 0 else 0 mm
            e1 = 1 mm if i == tails else 0 mm
            uv = [(l0 - e0, 0 mm), (r0 + e1, 0 mm), (r1 + e1, d), (r1 + e1, d + 1 mm),
                  (l1 - e0, d + 1 mm), (l1 - e0, d)]
            overrun = Polygon([(cx + q[0] * c - q[1] * s, cy + q[0] * s + q[1] * c) for q in uv],
                              overrun=true)
            Fixed(overrun)
        }
    } else {
        # the tails, `clearance` wider, open past the mate's edge at the line
        for i in range(tails) {
            m = -length / 2 + (i + 0.5) * p
            b0 = p / 4 - d / 2 * k + clearance / 2
            b1 = p / 4 + d / 2 * k + clearance / 2
            uv = [(m - b0, 0 mm), (m + b0, 0 mm), (m + b1, d), (m - b1, d)]
            cut = Polygon([(cx + q[0] * c - q[1] * s, cy + q[0] * s + q[1] * c) for q in uv])
            Fixed(cut)
            uv = [(m - b0, -1 mm), (m + b0, -1 mm), (m + b0, 0 mm), (m + b1, d), (m - b1, d), (m - b0, 0 mm)]
            overrun = Polygon([(cx + q[0] * c - q[1] * s, cy + q[0] * s + q[1] * c) for q in uv],
                              overrun=true)
            Fixed(overrun)
        }
    }
    Fixed(self)
}
