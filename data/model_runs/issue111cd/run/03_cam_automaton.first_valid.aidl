# Request (toys): a hand-cranked bobbing-duck automaton for a child, 4 mm ply, 6 mm dowels.
# Frame: a top 120 x 70 mm (corners r4) on two sides 70 wide x 100 tall, 100 mm apart
# centre to centre, each side glued into the top by two 12 mm tabs, with an arch cut from its
# bottom edge (a circle r24 centred 12 mm below the edge) so it stands on two feet.
# A 6 mm crank dowel runs through 6.4 mm holes 35 mm up in both sides; on it, between the
# sides, a round cam 44 mm across with its 6 mm axle hole 8 mm off centre (16 mm of lift);
# outside the right side a crank arm 40 mm between its two 6 mm holes (ends r7 and r6).
# A 6 mm follower dowel rises from the cam through a 6.5 mm hole in the middle of the top and
# carries a flat duck (about 64 x 48 mm) glued into a 6.2 x 7 mm notch under its belly; the
# duck has an eye hole and an engraved wing. Drawn with the cam down: the duck on the top.

import "std/joints.aidl"

thickness 4 mm
ply = 4 mm
axle_h = 35 mm
lift = 16 mm
side_x = 50 mm      # sides' centres from the middle

def side() -> solid {
    # frame: x along the depth, y up from the table; tabs' tips flush with the top's top face
    body = Rectangle(center=(0, 50), width=70, height=100)
    t = tab_and_slot(part="tab", length=70 mm, thickness=ply, tabs=2, tab=12 mm, screw=0,
                     cx=0 mm, cy=100 mm)
    hole axle { c = Circle(center=(0, axle_h), diameter=6.4) }
    hole arch { c = Circle(center=(0, -12), radius=24) }
}

assembly automaton {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=120, height=70, corner_radius=4)
        sl = tab_and_slot(part="slot", length=70 mm, thickness=ply, tabs=2, tab=12 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=0 mm)
        sr = tab_and_slot(part="slot", length=70 mm, thickness=ply, tabs=2, tab=12 mm, screw=0,
                          rotation=90 deg, cx=side_x, cy=0 mm)
        hole guide { c = Circle(center=(0, 0), diameter=6.5) }
    }
    left = side()
    right = side()

    solid cam {
        disc = Circle(center=(0, -lift / 2), diameter=44)   # drawn turned down
        hole axle { c = Circle(center=(0, 0), diameter=6) }
    }

    solid crank {
        arm = Hull(Circle(center=(0, 0), radius=7), Circle(center=(40, 0), radius=6))
        hole axle { c = Circle(center=(0, 0), diameter=6) }
        hole handle { c = Circle(center=(40, 0), diameter=6) }
    }

    solid duck {
        belly = Ellipse(center=(0, 14), rx=28, ry=14)
        head = Circle(center=(18, 38), radius=9)
        neck = Hull(Circle(center=(12, 20), radius=9), Circle(center=(18, 38), radius=9))
        beak = Polygon([(25, 40), (36, 37), (25, 33)])
        tail = Polygon([(-24, 20), (-36, 32), (-20, 26)])
        hole eye { c = Circle(center=(20, 40), radius=1.8) }
        hole dowel { r = Rectangle(center=(0, 2.5), width=6.2, height=7) }
        drawing wing { w = Arc(start=(-14, 16), through=(0, 9), end=(12, 18)) }
    }

    # 3D: top flat with its upper face at 100; sides in the y-z plane ((x, y, z) -> (z, x, y));
    # cam and crank on the crank axle; the duck stands up in the x-z plane on the top
    Place(top, position=(0, 0, 100 mm - ply), rotation=(0, 0, 0))
    Place(left, position=(-side_x - ply / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(side_x - ply / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(cam, position=(-ply / 2, 0, axle_h), rotation=(90 deg, 0, 90 deg))
    Place(crank, position=(side_x + ply / 2, 0, axle_h), rotation=(90 deg, 0, 90 deg))
    Place(duck, position=(0, ply / 2, 100), rotation=(90 deg, 0, 0))

    # on the sheet
    RightOf(left, top, gap=6)
    AlignTop(left, top)
    RightOf(right, left, gap=6)
    AlignTop(right, left)
    Below(cam, top, gap=6)
    AlignLeft(cam, top)
    RightOf(crank, cam, gap=6)
    AlignTop(crank, cam)
    Below(duck, left, gap=6)
    AlignLeft(duck, left)

    assert top.body.bb.width == 120 mm and top.body.bb.height == 70 mm, "top 120 x 70"
    assert left.body.bb.height == 100 mm and left.body.bb.width == 70 mm, "sides 70 x 100"
    assert top.sr.bb.center_x - top.sl.bb.center_x == 100 mm, "sides 100 apart"
    assert cam.disc.diameter == 44 mm, "cam 44 across"
    assert 2 * (cam.disc.center.y - cam.axle.c.center.y) == -16 mm, "16 mm of lift"
    assert crank.handle.c.center.x - crank.axle.c.center.x == 40 mm, "crank 40 mm"
    assert axle_h + 44 mm / 2 + lift / 2 < 100 mm - ply, "the cam turns under the top"
}
