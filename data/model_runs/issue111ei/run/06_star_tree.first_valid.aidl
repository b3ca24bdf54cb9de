# Request (holidays): a stacked-star Christmas tree for the sideboard, 3 mm ply on a 6 mm
# dowel. Twelve five-pointed star layers, tips R90 down to R24 in 6 mm steps, inner radius
# 0.45 of the tip radius, tips rounded R2, every other layer turned 36 degrees so the points
# alternate; each with a 6.2 mm hole in the middle. Between layers a spacer of three 20 mm
# washers (6.2 mm hole), so layers sit 12 mm apart. The base is three discs glued in a stack,
# 160, 130 and 100 across; the upper two have the 6.2 mm hole, the bottom one is solid so
# the dowel bottoms out on it. Round the bottom disc, outside the 130 disc, MERRY CHRISTMAS
# engraved (plain strokes, 8 mm) over the top on a 68 mm radius and 2026 under the bottom.
# On the dowel's tip an upright R30 star (rounded R2) with a 14 x 16 stem whose 6.2 x 12
# notch sits on the dowel, the stem resting on the top layer.

import "std/shapes.aidl"

thickness 3 mm

t = 3 mm
layers = 12
r0 = 90 mm
dr = 6 mm
gap_washers = 3
dowel_hole = 6.2 mm
z_first = 3 * t                     # the first layer sits on the base's three discs
pitch = t + gap_washers * t         # 12 mm, layer to layer
z_top = z_first + (layers - 1) * pitch + t    # the top layer's top face

def layer(r=90 mm, turn=0 deg) -> solid {
    s = Star(center=(0, 0), points=5, outer_radius=r, inner_radius=0.45 * r, rotation=turn,
             tip_radius=2)
    hole h { c = Circle(center=(0, 0), diameter=dowel_hole) }
}

def base_disc(d=160 mm, bored=true) -> solid {
    disc = Circle(center=(0, 0), diameter=d)
    if bored {
        hole h { c = Circle(center=(0, 0), diameter=dowel_hole) }
    }
}

assembly star_tree {
    for i in range(layers) {
        st = layer(r=r0 - i * dr, turn=36 deg if i % 2 == 1 else 0 deg)
        Place(st, position=(0, 0, z_first + i * pitch), face="up")
    }
    for j in range((layers - 1) * gap_washers) {
        w = washer(outer=20 mm, inner=dowel_hole)
        Place(w, position=(0, 0, z_first + (j // gap_washers) * pitch + t + (j % gap_washers) * t),
              face="up")
    }
    # the bottom disc is solid, and carries the greeting round its rim
    solid bottom {
        disc = Circle(center=(0, 0), diameter=160)
        drawing greeting {
            ring = Circle(center=(0, 0), radius=68, construction=true)
            top = Text("MERRY CHRISTMAS", along=ring, size=8)
            year = Text("2026", along=ring, size=8, flip=true)
        }
    }
    middle = base_disc(d=130 mm)
    upper = base_disc(d=100 mm)
    Place(bottom, position=(0, 0, 0), face="up")
    Place(middle, position=(0, 0, t), face="up")
    Place(upper, position=(0, 0, 2 * t), face="up")

    solid topper {
        s = Star(center=(0, 0), points=5, outer_radius=30, inner_radius=13.5, tip_radius=2)
        stem = Rectangle(center=(0, -18), width=14, height=16)
        hole notch { r = Rectangle(center=(0, -20), width=dowel_hole, height=12) }
    }
    # the stem's foot (y = -26 in its drawing) rests on the top layer
    Place(topper, position=(0, t / 2, z_top + 26), face="front", up="up")

    # laid out flat: stars in two rows, the base discs and the topper under them, then the
    # washers in rows of 11
    for i in range(1, layers) {
        if i == 6 {
            Below(st[6], st[0], gap=4)
            AlignLeft(st[6], st[0])
        } else {
            RightOf(st[i], st[i - 1], gap=4)
            AlignTop(st[i], st[i - 1])
        }
    }
    Below(bottom, st[6], gap=4)
    AlignLeft(bottom, st[6])
    RightOf(middle, bottom, gap=4)
    AlignTop(middle, bottom)
    RightOf(upper, middle, gap=4)
    AlignTop(upper, middle)
    RightOf(topper, upper, gap=4)
    AlignTop(topper, upper)
    Below(w[0], bottom, gap=4)
    AlignLeft(w[0], bottom)
    for j in range(1, len(w)) {
        if j % 11 == 0 {
            Below(w[j], w[j - 11], gap=4)
            AlignLeft(w[j], w[j - 11])
        } else {
            RightOf(w[j], w[j - 1], gap=4)
            AlignTop(w[j], w[j - 1])
        }
    }

    # the request's numbers
    assert len(st) == 12, "twelve layers"
    assert st[0].s.outer_radius == 90 mm and st[11].s.outer_radius == 24 mm, "R90 to R24"
    assert len(w) == 33, "three washers in each of 11 gaps"
    assert pitch == 12 mm, "layers 12 apart"
    assert bottom.disc.diameter == 160 mm and middle.disc.diameter == 130 mm and
        upper.disc.diameter == 100 mm, "base discs"
    assert topper.notch.r.width == 6.2 mm and topper.notch.r.height == 12 mm, "notch 6.2 x 12"
    assert topper.notch.r.bb.bottom == topper.stem.bb.bottom, "notch open at the stem's foot"
    assert distance(bottom.greeting.ring.center, bottom.disc.center) == 0 mm and
        bottom.greeting.ring.radius == 68 mm, "text on R68 round the disc's centre"
}
