# Request: a free-standing warning triangle for the workshop floor ("CAUTION"), cut
# from 6 mm ply and painted yellow, the engraving filled black.
# - An equilateral triangle 300 mm a side (its sharp-cornered size), corners rounded R15.
# - An engraved, filled border 18 mm wide starting 8 mm in from the edge.
# - A tapered exclamation mark cut through: the bar from an 18 mm round top centred
#   165 mm above the base to a 12 mm round bottom centred 95 mm above it; a 16 mm dot
#   centred 70 mm above the base.
# - "CAUTION" engraved filled, bold, 20 mm high, its baseline 36 mm above the base.
# - An 8 mm hanging hole at the top corner's centre; the border kept 3 mm clear round it.
# - It stands in a foot 200 long x 60 tall with a 60 wide top, cross-halved to it at the
#   middle of its base: both slots 30 deep, 6 + 0.2 wide. Two 5.5 mm peg holes in the
#   foot, 75 mm either side of the middle and 10 mm up.

units mm
t = 6 mm
thickness t
kerf 0.15 mm

import "std/joints.aidl"

side = 300 mm
r = 15 mm
tri_h = side * sqrt(3) / 2
# the rounded corners' centres: 2r from each sharp corner along its bisector
bl = (-side / 2 + 2 * r * cos(30 deg), r)
br = (side / 2 - 2 * r * cos(30 deg), r)
top = (0, tri_h - 2 * r)

assembly caution_sign {
    solid sign {
        c1 = Circle(center=bl, radius=r)
        c2 = Circle(center=br, radius=r)
        c3 = Circle(center=top, radius=r)
        plate = Hull(c1, c2, c3)
        hole mark {
            bar = Hull(Circle(center=(0, 165 mm), diameter=18 mm), Circle(center=(0, 95 mm), diameter=12 mm))
            dot = Circle(center=(0, 70 mm), diameter=16 mm)
        }
        hole hang { c = Circle(center=top, diameter=8 mm) }
        slot = cross_halving(depth=30 mm, thickness=t, clearance=0.2 mm, rotation=180 deg, cx=0, cy=0)
        drawing paint {
            e1 = Circle(center=bl, radius=r, construction=true)
            e2 = Circle(center=br, radius=r, construction=true)
            e3 = Circle(center=top, radius=r, construction=true)
            edge = Hull(e1, e2, e3, construction=true)
            inner = Inset(edge, 8 mm, construction=true)
            band = Shell(inner, -18 mm, fill=true)
            word = Text("CAUTION", position=(0, 36 mm), size=20 mm, font="sans:Bold", fill=true)
            hole keep_clear { k = Circle(center=top, diameter=8 mm + 2 * 3 mm) }
        }
        Fixed(c1)
        Fixed(c2)
        Fixed(c3)
        Fixed(mark)
        Fixed(hang)
        Fixed(paint)
    }

    solid foot {
        body = Trapezoid(center=(0, 30 mm), bottom_width=200 mm, top_width=60 mm, height=60 mm)
        slot = cross_halving(depth=30 mm, thickness=t, clearance=0.2 mm, cx=0, cy=60 mm)
        hole pegs {
            a = Circle(center=(-75 mm, 10 mm), diameter=5.5 mm)
            b = Circle(center=(75 mm, 10 mm), diameter=5.5 mm)
        }
        Fixed(body)
        Fixed(pegs)
    }

    # flat layout
    RightOf(foot, sign, gap=10)
    AlignBottom(foot, sign)

    # 3D: the sign faces the front, the foot across it (along y)
    Place(sign, position=(0, t / 2, 0), face="front", up="up")
    Place(foot, position=(-t / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert sign.c1.radius == 15 mm and abs(tri_h - 259.81 mm) < 0.01 mm
    assert sign.plate.bb.bottom == 0 mm, "base on the floor"
    assert sign.mark.dot.center.y - sign.plate.bb.bottom == 70 mm and sign.mark.dot.diameter == 16 mm
    assert sign.mark.bar.bb.top - sign.plate.bb.bottom == 165 mm + 9 mm
    assert sign.mark.bar.bb.bottom - sign.plate.bb.bottom == 95 mm - 6 mm
    assert sign.paint.word.position.y - sign.plate.bb.bottom == 36 mm
    assert sign.hang.c.diameter == 8 mm
    assert foot.body.bb.width == 200 mm and foot.body.bb.height == 60 mm and foot.body.top_width == 60 mm
    assert sign.slot.cut.bb.height == 30 mm and foot.slot.cut.bb.height == 30 mm
    assert sign.slot.cut.bb.width == 6.2 mm
    assert foot.pegs.b.center.x == 75 mm and foot.pegs.b.center.y - foot.body.bb.bottom == 10 mm
    # nothing runs into anything
    assert distance(sign.paint.word, sign.mark) >= 5 mm, "CAUTION clear of the dot"
    assert distance(sign.paint.word, sign.slot) >= 3 mm, "CAUTION clear of the foot slot"
    assert distance(sign.mark, sign.paint.band) >= 5 mm, "the mark inside the border"
    assert distance(sign.paint.word, sign.paint.band) >= 3 mm, "CAUTION inside the border"
    assert distance(foot.pegs, foot.slot) >= 20 mm
}
