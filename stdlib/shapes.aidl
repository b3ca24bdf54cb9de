# AIDL standard library: common shapes as templates.
#   import "std/shapes.aidl"
# Positions (cx, cy) are starting guesses: place an instance with constraints
# (CenterInside, Above, Coincident, ...) in the structure that uses it.

# A flat washer: a ring with a concentric bore, `outer` and `inner` their diameters.
# Members: `ring` (the Circle), `bore` (a hole; `bore.b` its Circle).
# Anchor: (cx, cy) is the centre of `ring`.
def washer(outer=10 mm, inner=5 mm, cx=0 mm, cy=0 mm) -> solid {
    assert inner > 0 mm and inner < outer - 1 mm, "the bore is more than 0 and leaves a ring more than 0.5 mm wide: 0 mm < inner < outer - 1 mm"
    ring = Circle(center=(cx, cy), diameter=outer)
    hole bore {
        b = Circle(center=(cx, cy), diameter=inner)
    }
    Concentric(bore.b, ring)
}

# Bolt holes evenly spaced on a circle. There are `count` holes of diameter
# `hole_d` on a circle of diameter `pcd` (pitch circle diameter), the first at
# angle `start`. Members: `pitch` (construction Circle), `bolt[i]` (Circles).
# Anchor: (cx, cy) is the centre of `pitch`.
def bolt_circle(count=6, pcd=40 mm, hole_d=5 mm, start=0 deg,
                cx=0 mm, cy=0 mm) -> hole {
    pitch = Circle(center=(cx, cy), diameter=pcd, construction=true)
    for i in range(count) {
        a = start + i * 360 deg / count
        bolt = Circle(center=(cx + pcd / 2 * cos(a), cy + pcd / 2 * sin(a)), diameter=hole_d)
        Coincident(bolt.center, polar(pitch.center, pcd / 2, a))  # exact: no sliding round
    }
}

# A mounting tab: a rectangle with a round end (pointing up) and a hole in
# it. `length` runs from the flat base to the tip of the round end;
# the round end is a half disc (a short tab, length under width, stays flat
# at its base), and the eye keeps a wall of more than 0.5 mm above the base.
# Members: `body` (the outline, a RoundedRectangle), `stem` (construction
# Rectangle, below the round end), `end` (construction Circle of the round
# end), `eye` (the hole; `eye.e`).
# Anchor: (cx, cy) is the middle of its bottom edge.
def rounded_tab(width=20 mm, length=20 mm, hole_d=6 mm, cx=0 mm, cy=0 mm) -> solid {
    assert hole_d > 0 mm and hole_d < width - 1 mm, "the eye leaves a wall more than 0.5 mm wide in the round end: hole_d < width - 1 mm"
    assert length > (width + hole_d) / 2 + 0.5 mm, "the eye leaves a wall more than 0.5 mm wide above the base: length > (width + hole_d) / 2 + 0.5 mm"
    body = RoundedRectangle(center=(cx, cy + length / 2), width=width, height=length,
                            corner_radii=[width / 2, width / 2, 0 mm, 0 mm])
    stem = Rectangle(bottom_left=(cx - width / 2, cy), width=width, height=length - width / 2, construction=true)
    end = Circle(center=(cx, cy + length - width / 2), diameter=width, construction=true)
    hole eye {
        e = Circle(center=(cx, cy + length - width / 2), diameter=hole_d)
    }
    Coincident(body.bottom.midpoint, stem.bottom.midpoint)
    Coincident(end.center, stem.top.midpoint)
    Concentric(eye.e, end)
}

# An oblong hole, e.g. for an adjustable screw. Member: `s` (a Slot).
# Anchor: (cx, cy) is the centre of `s`; rotation 0: the slot lies along x.
def slot_hole(length=20 mm, width=5 mm, rotation=0 deg, cx=0 mm, cy=0 mm) -> hole {
    s = Slot(center=(cx, cy), length=length, width=width, rotation=rotation)
}

# A hexagonal pocket for a nut, sized across flats (flats at top and bottom).
# Member: `hex` (a RegularPolygon).
# Anchor: (cx, cy) is the centre of `hex`.
def hex_pocket(across_flats=8 mm, cx=0 mm, cy=0 mm) -> hole {
    hex = RegularPolygon(center=(cx, cy), across_flats=across_flats, sides=6)
}
