# AIDL standard library: plates and the cut-outs laser-cut parts use most.
#   import "std/plates.aidl"
# Rounded and chamfered plates, keyholes, slots, a living hinge, and text set
# along an arc. docs/stdlib.md ("Plates and cut-outs") has pictures.

import "std/fasteners.aidl"

# A plate `width` x `height` with rounded corners of `corner_radius`.
# Member: `body`.
# Anchor: (cx, cy) is the centre of `body`.
def rounded_plate(width=80 mm, height=50 mm, corner_radius=5 mm, cx=0 mm, cy=0 mm) -> solid {
    body = RoundedRectangle(center=(cx, cy), width=width, height=height, corner_radius=corner_radius)
    Fixed(body.center)
}

# A plate `width` x `height` whose four corners are cut at 45 degrees,
# `chamfer` along each edge. Member: `body` (an octagon; `body.points[0]` is
# the bottom edge's left end, then counter-clockwise).
# Anchor: (cx, cy) is the centre of its box.
def chamfered_plate(width=80 mm, height=50 mm, chamfer=5 mm, cx=0 mm, cy=0 mm) -> solid {
    assert chamfer > 0 mm and 2 * chamfer < width and 2 * chamfer < height, "the chamfers must leave some of every edge"
    w = width / 2
    h = height / 2
    c = chamfer
    body = Polygon([(cx - w + c, cy - h), (cx + w - c, cy - h), (cx + w, cy - h + c), (cx + w, cy + h - c),
                    (cx + w - c, cy + h), (cx - w + c, cy + h), (cx - w, cy + h - c), (cx - w, cy - h + c)])
    Fixed(body.points[0])
}

# A rounded plate with a screw hole in each corner. The holes are
# clearance holes for a metric screw (`screw` 3: M3, ISO 273 `fit`),
# `inset` from both edges. Members: `body`,
# `corner[0..3]` (clearance_hole instances, counter-clockwise from the
# bottom left).
# Anchor: (cx, cy) is the centre of `body`.
def mounting_plate(width=80 mm, height=50 mm, corner_radius=4 mm, screw=3, fit="medium",
                   inset=6 mm, cx=0 mm, cy=0 mm) -> solid {
    assert len([s for s in metric_sizes if s == screw]) == 1, "`screw` is not a metric size: 2, 2.5, 3, 3.5, 4, 5, 6, 8, 10, 12, 16 or 20 (M2 to M20)"
    # each hole (a clearance hole at most 1.3 x screw across, at the coarse fit) keeps a wall
    # of more than 0.5 mm to the straight edges, the rounded corner and the next hole
    # the plate leaves the holes an inset between the two bounds below (the inset's range)
    assert height > 2.6 mm * screw + 1.5 mm, "the plate is too low for a hole at the top and the bottom: height > 2.6 mm * screw + 1.5 mm (or a smaller screw)"
    assert width > 2.6 mm * screw + 1.5 mm, "the plate is too narrow for a hole at the left and the right: width > 2.6 mm * screw + 1.5 mm (or a smaller screw)"
    assert inset > 0.65 mm * screw + 0.5 mm, "the holes break through the edges: inset > 0.65 mm * screw + 0.5 mm (a wall of 0.5 mm beside a clearance hole 1.3 x screw across)"
    assert inset < height / 2 - 0.65 mm * screw - 0.25 mm, "the holes at the top and bottom merge: inset < height / 2 - 0.65 mm * screw - 0.25 mm"
    assert inset < width / 2 - 0.65 mm * screw - 0.25 mm, "the holes at the left and right merge: inset < width / 2 - 0.65 mm * screw - 0.25 mm"
    assert corner_radius < (1.4142 * inset - 0.65 mm * screw - 0.5 mm) / 0.4142, "the rounded corners cut into the holes: corner_radius < (1.4142 * inset - 0.65 mm * screw - 0.5 mm) / 0.4142 (or a larger inset)"
    body = RoundedRectangle(center=(cx, cy), width=width, height=height, corner_radius=corner_radius)
    Fixed(body.center)
    for k in range(4) {
        sx = -1 if k == 0 or k == 3 else 1
        sy = -1 if k < 2 else 1
        corner = clearance_hole(size=screw, fit=fit, cx=cx + sx * (width / 2 - inset), cy=cy + sy * (height / 2 - inset))
        corner.c.center == body.center + (sx * (width / 2 - inset), sy * (height / 2 - inset))
    }
}

# A keyhole to hang a part on a screw. A round opening of `head` diameter for
# the screw head, at (cx, cy), and a slot of `slot_width` (the shank) running
# `length` from its center toward `direction` (90 deg: up, so the part drops
# onto the screw). Keep the slot inside the part: one that runs out through the
# edge is an open notch (W0530). Members: `head_hole` (Circle), `slot` (Slot).
# Anchor: (cx, cy) is the centre of `head_hole`.
def keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=0 mm, cy=0 mm) -> hole {
    assert slot_width > 0 mm and slot_width < head, "the slot must be narrower than the head opening"
    head_hole = Circle(center=(cx, cy), diameter=head)
    slot = Slot(start=(cx, cy), end=(cx + length * cos(direction), cy + length * sin(direction)), width=slot_width)
    Fixed(head_hole.center)
    Fixed(slot.start)
    Fixed(slot.end)
}

# A straight slot (stadium) `length` overall (tip to tip) and `width` wide,
# turned by `rotation`. Member: `s`.
# Anchor: (cx, cy) is the centre of `s`; rotation 0: the slot lies along x.
def slot(length=20 mm, width=5 mm, rotation=0 deg, cx=0 mm, cy=0 mm) -> hole {
    s = Slot(center=(cx, cy), length=length, width=width, rotation=rotation)
    Fixed(s.center)
}

# A living hinge: staggered cuts that let stiff sheet bend. The band is
# `width` x `height` (centered at (cx, cy)) and bends about its long axis (y). Columns of cuts `pitch` apart; each cut is `cut`
# long, ONE line the laser cuts once (a through-cut: the slit is one kerf
# wide), with `bridge` of material between cuts of a column; `kerf_width` > 0
# cuts each as a slot that wide instead (a router's or a thick sheet's). Every
# second column is shifted by half a period, and its end cuts reach the
# band's top and bottom (a slot runs `overrun` past them), so a band as tall
# as the plate opens at its edges, as the hinge needs. A column holds the
# whole cuts that fit, floor((height - bridge) / (cut + bridge)), centred: the
# rest of the height is uncut at both ends of the unshifted columns (`height`
# 32 mm of 15 + 3 mm periods: one cut, 8.5 mm uncut each end, end cuts of 14.5
# mm); a height of n periods less a bridge leaves a bridge. There are
# floor(width / pitch) + 1 columns, centred: the outer ones lie
# (width - (columns - 1) * pitch) / 2 in from the band's sides, and the box an
# instance's `.bb` reads is its cuts', that much narrower than the band where
# `width` is no whole number of pitches (41.5 mm at pitch 2: 0.75 mm in each
# side). Members: `cut_a` (the full-length cuts, per column), `cut_b` (the end
# cuts).
# Anchor: (cx, cy) is the centre of its box.
def living_hinge(width=30 mm, height=60 mm, pitch=2 mm, cut=15 mm, bridge=3 mm,
                 kerf_width=0 mm, overrun=1 mm, cx=0 mm, cy=0 mm) -> cut {
    assert width > 0 mm and height > 0 mm, "the hinge's width and height are more than 0"
    assert pitch > 0 mm and cut > 0 mm and bridge > 0 mm, "the pitch, the cuts and the bridges are more than 0"
    assert kerf_width >= 0 mm and overrun >= 0 mm, "the kerf width and the overrun are 0 or more"
    period = cut + bridge
    rows = max(1, floor((height - bridge) / period))
    cols = max(1, floor(width / pitch) + 1)
    x0 = cx - (cols - 1) * pitch / 2
    slot = kerf_width > 0 mm
    for i in range(cols) {
        x = x0 + i * pitch
        shifted = i % 2 == 1
        # the full cuts of the column
        n = rows - 1 if shifted else rows
        for k in range(n) {
            y = cy + (k - (n - 1) / 2) * period
            if slot {
                cut_a = Rectangle(center=(x, y), width=kerf_width, height=cut)
            } else {
                cut_a = Line(start=(x, y - cut / 2), end=(x, y + cut / 2))
            }
            Fixed(cut_a)
        }
        # a shifted column ends in two cuts through the band's edges
        if shifted {
            inner = rows / 2 * period - cut / 2
            for s in [-1, 1] {
                top = cy + s * (height / 2 + (overrun if slot else 0 mm))
                if slot {
                    cut_b = Rectangle(center=(x, (top + cy + s * inner) / 2), width=kerf_width, height=abs(top - cy - s * inner))
                } else {
                    cut_b = Line(start=(x, cy + s * inner), end=(x, top))
                }
                Fixed(cut_b)
            }
        }
    }
}

# Text set along an arc, to engrave. The `text` follows a circle of `radius`
# about (cx, cy), centered on the direction `angle` (90 deg: over the top),
# reading clockwise (left to right across the top), one Text per character,
# their baselines on the circle. Characters are placed `spacing` x `size` apart along the arc (the
# font is proportional, so this spacing is an average: wide letters sit a
# little closer). Members: `ch` (the characters' Texts, spaces left out).
# Anchor: (cx, cy) is the centre of the circle its baselines follow.
def text_on_arc(text="AIDL", radius=30 mm, size=5 mm, angle=90 deg, spacing=0.9,
                cx=0 mm, cy=0 mm) -> drawing {
    assert radius > 0 mm and size > 0 mm, "the arc's radius and the text's size are more than 0"
    assert spacing > 0, "the spacing is more than 0"
    n = len(text)
    step = spacing * size / radius * 1 rad
    for i in range(n) {
        if text[i] != " " {
            a = angle + ((n - 1) / 2 - i) * step
            ch = Text(text[i], position=(cx + radius * cos(a), cy + radius * sin(a)), size=size,
                      anchor="middle", rotation=a - 90 deg)
            Fixed(ch.position)
        }
    }
}
