# Request: a directional fingerpost for our allotment gate, from 6 mm exterior plywood:
# - the post: two fins 450 mm tall x 60 mm wide that slot together into a cross (cross-halving
#   joint: one slotted 225 mm down from its top, the other 225 mm up from its bottom, slots for
#   6 mm ply with 0.2 mm clearance); each fin has two tabs 12 mm wide x 6 mm deep under its
#   bottom edge, centred 21 mm either side of its middle;
# - a base 160 x 160 mm (10 mm corners) with four 12.2 x 6.2 mm mortises for the tabs, in a
#   cross round the centre, and four 4.5 mm screw holes countersunk 9 mm, 15 mm in from the
#   corners' edges, to screw it to the gatepost top;
# - two arrow-shaped arms 220 mm long x 50 mm tall, the point 30 mm long; each is screwed to a
#   fin's face by two 3.5 mm holes countersunk 7 mm, 10 mm and 23 mm from its square end, on its
#   centre line; the place name engraved as filled bold letters 18 mm tall, at most 140 mm
#   wide, centred between 30 mm from the square end and the point's root:
#   "ALLOTMENTS" on one, "CAFE 200 m" on the other.

import "std/joints.aidl"

units mm
thickness 6 mm

def arm(label="ALLOTMENTS") -> solid {
    board = Polygon([(0, -25), (190, -25), (220, 0), (190, 25), (0, 25)])
    hole screws {
        a = Circle(center=(10, 0), diameter=3.5)
        b = Circle(center=(23, 0), diameter=3.5)
    }
    Countersink(screws, diameter=7 mm)
    drawing name {
        t = Text(label, position=(110, 0), size=18, font="sans:Bold", valign="middle",
                 fill=true, max_width=140 mm)
    }
    assert board.bb.width == 220 mm and board.bb.height == 50 mm, "arm 220 x 50"
    assert screws.a.center.x - board.bb.left == 10 mm and screws.b.center.x - board.bb.left == 23 mm, "screws 10 and 23 mm in"
    assert name.bb.width <= 140 mm, "name at most 140 mm wide"
    assert distance(name, screws) >= 5 mm, "name clear of the screws"
    assert name.bb.right <= board.bb.left + 190 mm, "name before the point"
}

def fin(from_top=true) -> solid {
    body = Rectangle(center=(0, 225), width=60, height=450)
    tab_l = Rectangle(center=(-21, -2.5), width=12, height=7)
    tab_r = Rectangle(center=(21, -2.5), width=12, height=7)
    if from_top {
        slot = cross_halving(depth=225 mm, thickness=6 mm, clearance=0.2 mm, cx=0 mm, cy=450 mm)
    } else {
        slot = cross_halving(depth=225 mm, thickness=6 mm, clearance=0.2 mm, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    assert body.bb.width == 60 mm and body.bb.height == 450 mm, "fin 450 x 60"
    assert body.bb.bottom - tab_l.bb.bottom == 6 mm, "tabs 6 mm deep"
}

assembly fingerpost {
    fin_a = fin(from_top=true)
    fin_b = fin(from_top=false)

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=160, height=160, corner_radius=10)
        hole mortise {
            m_e = Rectangle(center=(21, 0), width=12.2, height=6.2)
            m_w = Rectangle(center=(-21, 0), width=12.2, height=6.2)
            m_n = Rectangle(center=(0, 21), width=6.2, height=12.2)
            m_s = Rectangle(center=(0, -21), width=6.2, height=12.2)
        }
        hole screw {
            c = Circle(center=(-65, -65), diameter=4.5)
        }
        screws = CornerPattern(screw, plate, inset=15)
        Countersink(screws, diameter=9 mm)
        assert len(screws) == 4, "four screws"
    }

    arm1 = arm(label="ALLOTMENTS")
    arm2 = arm(label="CAFE 200 m")

    RightOf(fin_b, fin_a, gap=10)
    AlignTop(fin_b, fin_a)
    RightOf(base, fin_b, gap=10)
    AlignTop(base, fin_b)
    Below(arm1, base, gap=10)
    AlignLeft(arm1, base)
    Below(arm2, arm1, gap=10)
    AlignLeft(arm2, arm1)

    assert fin_a.slot.depth + fin_b.slot.depth == 450 mm, "halvings meet across the full height"
    assert base.mortise.m_e.center.x - base.plate.center.x == 21 mm, "mortises under the tabs"
}
