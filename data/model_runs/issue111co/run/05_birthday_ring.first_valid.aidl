# Request: a birthday ring for the kids' party table (the Scandinavian kind): a flat
# ring 290 mm across with a 50 mm band, 16 holes of 12.5 mm for the candle holders
# and little wooden figures, evenly round on a 256 mm circle, "HAPPY BIRTHDAY"
# engraved along the bottom of the band, and the child's age, 80 mm tall bold
# figures on a base rail, standing at the top of the ring on a 20 mm tenon glued in
# a mortise. 4 mm birch ply. This year: 6.

units mm
thickness 4 mm

param age = 6, min = 1, max = 99
param od = 290 mm, min = 220 mm, max = 380 mm
param band = 50 mm, min = 40 mm, max = 70 mm
param holes = 16, min = 8, max = 24
param peg_d = 12.5 mm, min = 10 mm, max = 16 mm
param fig_h = 80 mm, min = 50 mm, max = 110 mm

t = 4 mm
pcd = 256 mm
tenon_w = 20 mm
rail_h = 6 mm
mortise_r = od / 2 - band + 13 mm      # the mortise's centre line, inside the holes

def peg() -> hole {
    c = Circle(center=(0, 0), diameter=peg_d)
}

assembly birthday_ring {
    solid ring {
        outer = Circle(center=(0, 0), diameter=od)
        hole middle {
            c = Circle(center=(0, 0), diameter=od - 2 * band)
        }
        first = peg()
        Coincident(first.c.center, polar(outer.center, pcd / 2, 90 deg + 180 deg / holes))
        pegs = CircularPattern(first, holes, outer.center)
        hole mortise {
            m = Rectangle(center=(0, mortise_r), width=tenon_w, height=t)
        }
        drawing words {
            path = Circle(center=(0, 0), radius=od / 2 - band + 15, construction=true)
            w = Text("HAPPY BIRTHDAY", along=path, size=9, flip=true, valign="middle")
        }
    }

    solid figure {
        tenon = Rectangle(corner=(-tenon_w / 2, 0), opposite=(tenon_w / 2, t))
        n = Text(str(age), position=(0, t + rail_h - 1), size=fig_h, font="sans:Bold")
        rail = Rectangle(corner=(n.bb.left, t), opposite=(n.bb.right, t + rail_h))
    }

    RightOf(figure, ring, gap=8)
    AlignBottom(figure, ring)

    # assembled: the ring flat on the table, the figure standing in its mortise, facing front
    Place(ring, position=(0, 0, 0))
    Place(figure, position=(0, mortise_r + t / 2, 0), face="front", up="up")

    # the request's numbers
    assert ring.outer.diameter == 290 mm, "290 mm across"
    assert (ring.outer.diameter - ring.middle.c.diameter) / 2 == 50 mm, "50 mm band"
    assert len(ring.pegs) == 16 and ring.first.c.diameter == 12.5 mm, "16 holes of 12.5 mm"
    assert distance(ring.first.c.center, ring.outer.center) == 256 mm / 2, "on a 256 mm circle"
    assert figure.n.size == 80 mm, "80 mm figures"
    assert figure.tenon.bb.width == 20 mm and ring.mortise.m.width == 20 mm, "20 mm tenon"
    assert ring.mortise.bb.bottom > ring.middle.bb.top + 3 mm, "mortise inside the band"
    assert figure.bb.width <= 400 mm and ring.bb.width <= 600 mm, "fits the bed"
}
