# Request: three hiking-staff medallions to nail onto a walking stick, 1.5 mm birch ply.
# - Each a shield 36 wide x 46 tall: a flat top with R4 corners, straight sides for 20 mm,
#   then two arcs (tangent to the sides) meeting in a point at the bottom.
# - Two 1.5 mm nail holes on the centre line, 4 mm from the top edge and 4 mm from the
#   bottom point.
# - Engraved: the peak's name arched over a filled mountain silhouette (the name's
#   baseline on a circle R14 whose centre is 2 mm below the shield's middle, at most 30 mm
#   long along it, 4.5 mm tall), and the height "NNNN m" 3.5 mm tall, its baseline 15 mm
#   below the middle.
# - Peaks: BEN NEVIS 1345, SNOWDON 1085, SCAFELL PIKE 978.

thickness 1.5 mm

HW = 18 mm                    # half width
TOP = 23 mm
Y0 = 3 mm                     # where the sides turn into the arcs (20 below the top)
BOT = -23 mm
R = (HW ** 2 + (Y0 - BOT) ** 2) / (2 * HW)    # an arc tangent to the side at Y0 through the point
PEAKS = [["BEN NEVIS", 1345], ["SNOWDON", 1085], ["SCAFELL PIKE", 978]]

def medallion(name="PEAK", metres=1000) -> solid {
    top = Line((-HW, TOP), (HW, TOP))
    rs = Line((HW, TOP), (HW, Y0))
    ra = Arc(center=(HW - R, Y0), start=(0, BOT), end=(HW, Y0))
    la = Arc(center=(-HW + R, Y0), start=(-HW, Y0), end=(0, BOT))
    ls = Line((-HW, Y0), (-HW, TOP))
    Fillet([top, rs], 4)
    Fillet([ls, top], 4)
    hole nails {
        a = Circle(center=(0, TOP - 4 mm), diameter=1.5)
        b = Circle(center=(0, BOT + 4 mm), diameter=1.5)
    }
    drawing art {
        ring = Circle(center=(0, -2), radius=14, construction=true)
        word = Text(name, along=ring, size=4.5, max_width=30)
        peak = Polygon([(-12, -8), (-5, 4), (-2, 0), (3, 8), (12, -8)], fill=true)
        height = Text(str(metres) + " m", position=(0, -15), size=3.5)
    }
}

assembly medallions {
    for i in range(3) {
        m = medallion(name=PEAKS[i][0], metres=PEAKS[i][1])
    }
    RightOf(m[1], m[0], gap=5)
    AlignBottom(m[1], m[0])
    RightOf(m[2], m[1], gap=5)
    AlignBottom(m[2], m[0])

    assert len(m) == 3, "three medallions"
    assert m[0].bb.width == 36 mm and m[0].bb.height == 46 mm, "36 x 46"
    assert m[0].top.start.y - m[0].rs.end.y == 20 mm, "sides 20"
    assert m[0].nails.a.center.y - m[0].nails.b.center.y == 38 mm, "nails 4 from the ends"
    assert m[0].nails.a.diameter == 1.5 mm, "1.5 mm nails"
    for i in range(3) {
        assert distance(m[i].art, m[i].nails) >= 1 mm, "engraving clear of the nails"
        assert m[i].art.bb.width <= m[i].bb.width - 4 mm, "engraving inside the shield"
    }
}
