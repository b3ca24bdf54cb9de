# Request (toys): a Tower of Hanoi puzzle in 6 mm plywood. A base 220 x 100 mm with 6 mm corner
# radii and three 8.2 mm holes for 8 mm dowel pegs (the pegs are bought dowels, not cut), on
# 70 mm centres, the middle one in the middle of the base's length, all 40 mm from the back
# edge. "TOWER OF HANOI" engraved along the front as 7 mm serif letter outlines, centred, its
# baseline 8 mm above the front edge. Four discs, 70, 58, 46 and 34 mm across, each with a 10 mm
# bore to slide over the pegs and its number (1 for the largest .. 4) engraved as a filled bold
# numeral, half the ring's width tall but at most 10 mm, centred between the bore and the rim
# above the bore. Parts laid flat, 6 mm apart, for cutting.

thickness 6 mm

param pitch = 70 mm, min = 60 mm, max = 90 mm
peg_hole = 8.2 mm
bore_d = 10 mm

def disc(d=70 mm, num=1) -> solid {
    ring = Circle(center=(0, 0), diameter=d)
    hole bore {
        c = Circle(center=(0, 0), diameter=bore_d)
    }
    drawing mark {
        t = Text(str(num), ((0, (d / 2 + bore_d / 2) / 2)), size=min(10 mm, (d - bore_d) / 4),
                 font="sans:Bold", fill=true, valign="middle")
    }
}

assembly hanoi {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=220, height=100, corner_radius=6)
        hole pegs {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 10), diameter=peg_hole)
            }
        }
        drawing title {
            t = Text("TOWER OF HANOI", (0, -42), size=7, font="serif")
        }
        AlignCenterX(pegs, body)
        pegs.c[0].center.y == body.bb.top - 40 mm
        AlignCenterX(title, body)
        title.t.position.y == body.bb.bottom + 8 mm
    }
    d1 = disc(d=70 mm, num=1)
    d2 = disc(d=58 mm, num=2)
    d3 = disc(d=46 mm, num=3)
    d4 = disc(d=34 mm, num=4)

    Below(d1, base, gap=6)
    AlignLeft(d1, base)
    RightOf(d2, d1, gap=6)
    AlignTop(d2, d1)
    RightOf(d3, d2, gap=6)
    AlignTop(d3, d2)
    RightOf(d4, d3, gap=6)
    AlignTop(d4, d3)

    assert abs(base.body.width - 220 mm) < 0.01 mm and abs(base.body.height - 100 mm) < 0.01 mm, "base 220 x 100"
    assert len(base.pegs.c) == 3, "three pegs"
    assert abs(base.pegs.c[1].center.x - base.pegs.c[0].center.x - 70 mm) < 0.01 mm, "70 mm centres"
    assert abs(base.pegs.c[1].center.x - base.body.center.x) < 0.01 mm, "middle peg in the middle"
    assert abs(base.body.bb.top - base.pegs.c[2].center.y - 40 mm) < 0.01 mm, "40 from the back"
    assert abs(d1.ring.diameter - 70 mm) < 0.01 mm and abs(d2.ring.diameter - 58 mm) < 0.01 mm and abs(d3.ring.diameter - 46 mm) < 0.01 mm and abs(d4.ring.diameter - 34 mm) < 0.01 mm, "discs 70, 58, 46, 34"
    assert abs(d4.bore.c.diameter - 10 mm) < 0.01 mm, "10 mm bores"
    assert d4.mark.bb.bottom > d4.bore.bb.top and d4.mark.bb.top < d4.ring.bb.top, "numeral between bore and rim"
    assert base.title.bb.top < base.body.bb.top - 40 mm - 35 mm, "title clear of the largest disc"
    assert d4.bb.right <= base.bb.right + 40 mm, "the discs' row about the base's length"
}
