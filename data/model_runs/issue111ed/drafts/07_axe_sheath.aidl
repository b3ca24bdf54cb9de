# Request (camping): a layered sheath for my hatchet's bit, 3 mm ply, three
# layers: front, a spacer the blade sits in, back. The bit (side view) is 60 mm
# wide where it leaves the eye, its cheeks flare to 100 mm over 70 mm, and the
# cutting edge is an arc through both corners bulging 15 mm further (85 mm from
# the eye). Each layer is the bit grown by 16 mm all round, cut off straight
# level with the eye. The spacer has the bit's shape cut out with 1 mm clearance,
# open at the top so the blade slides in. Four M5 Chicago screws through all three
# layers, 8 mm outside the bit: two on the cheeks (level with their middles) and
# two beside the edge, 20 deg either side of its lowest point; two 5 mm holes
# 6 mm below the top, 41 mm either side of the centre, for a bungee loop over the
# head. The front has a little pine tree (three stacked triangles) and "KEEP
# SHARP" engraved filled (6 mm).

import "std/fasteners.aidl"

units mm
thickness 3 mm

EYE_W = 60 mm         # bit width at the eye
EDGE_W = 100 mm       # across the edge's corners
FLARE = 70 mm         # eye to the edge's corners
DEPTH = 85 mm         # eye to the edge's lowest point
MARGIN = 16 mm
SCREW_OUT = 8 mm
# the edge arc's centre (0, C) and radius through (+-50, -70) and (0, -85)
C = ((EDGE_W / 2) ** 2 + FLARE ** 2 - DEPTH ** 2) / (2 * (DEPTH - FLARE))
R = DEPTH + C
A0 = 180 deg + atan((FLARE + C) / (EDGE_W / 2))   # the edge's left corner, seen from (0, C)
A1 = 360 deg - atan((FLARE + C) / (EDGE_W / 2))   # its right corner
# a cheek's outward unit normal (left cheek; the right is its mirror)
CHEEK_LEN = sqrt(((EDGE_W - EYE_W) / 2) ** 2 + FLARE ** 2)
NX = -FLARE / CHEEK_LEN
NY = (EDGE_W - EYE_W) / 2 / CHEEK_LEN
MID_X = -(EYE_W + EDGE_W) / 4
MID_Y = -FLARE / 2

# front (kind=0), spacer (kind=1), back (kind=2)
def layer(kind=0) -> solid {
    # the edge arc as a pie slice (Hull takes closed shapes): the hull of the eye's two
    # corners and the slice is the bit below the eye line
    b = Hull(Point(-EYE_W / 2, 0), Point(EYE_W / 2, 0),
             Sector(center=(0, C), radius=R, start_angle=A0, end_angle=A1))
    grown = Offset(b, MARGIN)
    keep = Rectangle(corner=(-150, 0), opposite=(150, -150))
    outline = Intersect(grown, keep)
    Fixed(outline)

    s1 = clearance_hole(size=5, fit="fine", cx=MID_X + SCREW_OUT * NX, cy=MID_Y + SCREW_OUT * NY)
    s2 = clearance_hole(size=5, fit="fine", cx=-(MID_X + SCREW_OUT * NX), cy=MID_Y + SCREW_OUT * NY)
    s3 = clearance_hole(size=5, fit="fine", cx=(R + SCREW_OUT) * cos(-110 deg),
                        cy=C + (R + SCREW_OUT) * sin(-110 deg))
    s4 = clearance_hole(size=5, fit="fine", cx=(R + SCREW_OUT) * cos(-70 deg),
                        cy=C + (R + SCREW_OUT) * sin(-70 deg))
    hole bungee {
        l = Circle(center=(-41, -6), diameter=5)
        r = Circle(center=(41, -6), diameter=5)
    }

    if kind == 1 {
        hole pocket {
            bb2 = Hull(Point(-EYE_W / 2, 0), Point(EYE_W / 2, 0),
                       Sector(center=(0, C), radius=R, start_angle=A0, end_angle=A1))
            blade = Offset(bb2, 1)
            mouth = Rectangle(center=(0, 2), width=EYE_W + 2, height=6, overrun=true)
        }
    }
    if kind == 0 {
        drawing tree {
            t1 = Triangle(center=(0, -16), base=14, height=9, fill=true)
            t2 = Triangle(center=(0, -22), base=20, height=10, fill=true)
            t3 = Triangle(center=(0, -29), base=26, height=11, fill=true)
            trunk = Rectangle(center=(0, -36.5), width=4, height=7, fill=true)   # up into t3
        }
        drawing words {
            w = Text("KEEP SHARP", position=(0, -55), size=6, valign="middle",
                     font="sans:Bold", fill=true)
        }
    }
}

assembly axe_sheath {
    front = layer(kind=0)
    spacer = layer(kind=1)
    back = layer(kind=2)

    RightOf(spacer, front, gap=5)
    AlignTop(spacer, front)
    RightOf(back, spacer, gap=5)
    AlignTop(back, front)

    # stacked: back on the bench, spacer on it, front on top
    Place(back, position=(0, 0, 0), face="up")
    Place(spacer, position=(0, 0, 3), face="up")
    Place(front, position=(0, 0, 6), face="up")

    # the request's numbers
    assert abs(front.outline.bb.width - (100 mm + 2 * 16 mm)) < 0.5 mm, "bit grown 16 all round"
    # (the hull with the Sector reaches 5.8 mm above the eye line, to the slice's centre:
    # the eye line is y = 0)
    assert abs(front.outline.bb.top - 0 mm) < 0.001 mm, "cut off level with the eye"
    assert abs(front.b.bb.bottom - 0 mm + 85 mm) < 0.01 mm, "edge 85 from the eye"
    assert distance(front.s1, front.b) >= 8 mm - 2.7 mm - 0.1 mm, "cheek screws 8 mm out"
    assert distance(front.s3, front.b) >= 8 mm - 2.7 mm - 0.1 mm, "edge screws 8 mm out"
    assert distance(spacer.s1, spacer.pocket) >= 3 mm, "screws clear of the pocket"
    assert distance(spacer.bungee, spacer.pocket) >= 3 mm, "bungee holes clear of the pocket"
    assert distance(front.words, front.s1) >= 3 mm and distance(front.words, front.s2) >= 3 mm,
        "words clear of the screws"
    assert distance(front.tree, front.words) >= 3 mm, "tree clear of the words"
}
