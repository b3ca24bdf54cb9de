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
# Members: `outline` (construction rectangle of the outer size), `core`.
def finger_panel(width=100 mm, height=60 mm, thickness=3 mm, finger=10 mm,
                 bottom="fingers", right="fingers", top="fingers", left="fingers",
                 cx=0 mm, cy=0 mm) -> solid {
    t = thickness
    kinds = [bottom, right, top, left]
    for kind in kinds {
        assert (1 if kind == "fingers" or kind == "slots" or kind == "flat" else 0) == 1, "an edge is \"fingers\", \"slots\" or \"flat\""
    }
    assert width > 2 * t and height > 2 * t, "a panel must be larger than twice the thickness"
    outline = Rectangle(center=(cx, cy), width=width, height=height, construction=true)
    core = Rectangle(center=(cx, cy), width=width - 2 * t, height=height - 2 * t)
    Fixed(core.center)
    core.center == outline.center
    # the tabs of each edge (bottom, right, top, left), reaching t/2 into the core
    for e in range(4) {
        kind = kinds[e]
        run = (width if e % 2 == 0 else height) - 2 * t
        # the largest odd count of segments at least `finger` wide; at least 3 (narrower
        # fingers) while they stay `thickness` wide, so that the joint interlocks
        q = floor(run / finger)
        odd = q if q % 2 == 1 else q - 1
        n = 1 if kind == "flat" else (odd if odd >= 3 else (3 if run >= 3 * t else 1))
        w = run / n
        for i in range(n) {
            if kind == "flat" or (kind == "fingers") == (i % 2 == 0) {
                s = t + (i + 0.5) * w
                side_x = cx + width / 2 - 0.75 * t if e == 1 else cx - width / 2 + 0.75 * t
                side_y = cy - height / 2 + 0.75 * t if e == 0 else cy + height / 2 - 0.75 * t
                tx = cx - width / 2 + s if e % 2 == 0 else side_x
                ty = cy - height / 2 + s if e % 2 == 1 else side_y
                tab = Rectangle(center=(tx, ty), width=w if e % 2 == 0 else 1.5 * t,
                                height=w if e % 2 == 1 else 1.5 * t)
                Fixed(tab.center)
            }
        }
    }
    # corner squares (bottom-left, bottom-right, top-right, top-left)
    for c in range(4) {
        if kinds[c] != "slots" and kinds[(c + 3) % 4] != "slots" {
            sx = -1 if c == 0 or c == 3 else 1
            sy = -1 if c < 2 else 1
            corner = Rectangle(center=(cx + sx * (width / 2 - 0.75 * t), cy + sy * (height / 2 - 0.75 * t)),
                               width=1.5 * t, height=1.5 * t)
            Fixed(corner.center)
        }
    }
}

# A finger-jointed box as six flat panels (`closed=false`: open-top, no lid).
# Its outer size is `length` x `depth` x `height` from material `thickness`;
# the panels are laid out flat (a net, `gap` apart) around the bottom
# centered at (cx, cy): front
# below it, back above it, the lid above the back, left and right beside it.
# The front and back have fingers on every edge and keep their corners; the
# bottom and lid have slots along the front and back and fingers at the
# sides; the sides have slots all round. Members: `bottom`, `front`, `back`,
# `left`, `right`, `lid` (each a finger_panel). Each panel is placed in 3D
# (`Place`): assembled (`aidl render --assembled`), the box stands on z = 0,
# centered on x = y = 0, its fingers in their slots.
def finger_box(length=120 mm, depth=80 mm, height=50 mm, thickness=3 mm,
               finger=10 mm, closed=true, gap=5 mm, cx=0 mm, cy=0 mm) -> assembly {
    open = "slots" if closed else "flat"
    bottom = finger_panel(width=length, height=depth, thickness=thickness, finger=finger,
                          bottom="slots", right="fingers", top="slots", left="fingers", cx=cx, cy=cy)
    front = finger_panel(width=length, height=height, thickness=thickness, finger=finger,
                         top="fingers" if closed else "flat", cx=cx, cy=cy - (depth + height) / 2 - gap)
    back = finger_panel(width=length, height=height, thickness=thickness, finger=finger,
                        top="fingers" if closed else "flat", cx=cx, cy=cy + (depth + height) / 2 + gap)
    left = finger_panel(width=height, height=depth, thickness=thickness, finger=finger,
                        bottom="slots", right="slots", top="slots", left=open,
                        cx=cx - (length + height) / 2 - gap, cy=cy)
    right = finger_panel(width=height, height=depth, thickness=thickness, finger=finger,
                         bottom="slots", right=open, top="slots", left="slots",
                         cx=cx + (length + height) / 2 + gap, cy=cy)
    bottom.outline.center == (cx, cy)
    front.outline.center == (cx, cy - (depth + height) / 2 - gap)
    back.outline.center == (cx, cy + (depth + height) / 2 + gap)
    left.outline.center == (cx - (length + height) / 2 - gap, cy)
    right.outline.center == (cx + (length + height) / 2 + gap, cy)
    if closed {
        lid = finger_panel(width=length, height=depth, thickness=thickness, finger=finger,
                           bottom="slots", right="fingers", top="slots", left="fingers",
                           cx=cx, cy=cy + depth + height + 2 * gap)
        lid.outline.center == (cx, cy + depth + height + 2 * gap)
        Place(lid, position=(-cx, -(cy + depth + height + 2 * gap), height - thickness))
    }
    # assembled: each panel folded up from the net about its edge on the bottom
    Place(bottom, position=(-cx, -cy, 0 mm))
    Place(front, rotation=(90 deg, 0, 0),
          position=(-cx, thickness - depth / 2, height / 2 - (cy - (depth + height) / 2 - gap)))
    Place(back, rotation=(90 deg, 0, 0),
          position=(-cx, depth / 2, height / 2 - (cy + (depth + height) / 2 + gap)))
    Place(left, rotation=(0, 90 deg, 0),
          position=(-length / 2, -cy, cx - (length + height) / 2 - gap + height / 2))
    Place(right, rotation=(0, -90 deg, 0),
          position=(length / 2, -cy, height / 2 - (cx + (length + height) / 2 + gap)))
}
