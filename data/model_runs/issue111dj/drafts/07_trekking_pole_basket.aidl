# Request: a pair of snow baskets for trekking poles, 2 mm polypropylene. Each a disc
# 100 mm across with a 10 mm bore for the pole's tip and six radial grip slits, 5 mm long
# from the bore's edge, so the bore grips the pole. Six windows in a ring to shed snow:
# arc slots on radius 30, 14 mm wide, each spanning 40 degrees, leaving 20 degree spokes
# centred on 0, 60, 120 ... degrees. The rim scalloped with twelve R5 bites centred on the
# rim, every 30 degrees from 0. "SNOW BASKET" engraved (3.5 mm letters) on a circle of
# radius 39 over the top, between the windows and the bites.
# FIX after the first valid program: W0504 (the disc falls apart into 2 pieces) and W0508
# (each window overlaps its neighbours by 3.58 mm) were real: an ArcSlot's angles are its
# end caps' CENTRES, and the R7 caps reach about 13.5 deg further at radius 30, so the
# "20 degree spokes" were gone and the hub fell out of the rim. The windows are now ring
# pieces (Sector with inner_radius) from radius 23 to 37 spanning exactly 10..50 deg, their
# corners rounded R3: spokes 20 deg (8 mm at the inner edge).

thickness 2 mm

def basket() -> solid {
    disc = Circle(center=(0, 0), diameter=100)
    hole bore {
        c = Circle(center=(0, 0), diameter=10)
    }
    cut grip {
        for i in range(6) {
            # from inside the bore out to 5 mm past its edge
            l = Line(polar((0, 0), 4, i * 60 deg), polar((0, 0), 10, i * 60 deg))
        }
    }
    hole window {
        w = Sector(center=(0, 0), radius=37, start_angle=10 deg, end_angle=50 deg,
                   inner_radius=23)
        Fillet(3)
    }
    windows = CircularPattern(window, 6, (0, 0))
    hole bite {
        b = Circle(center=(50, 0), radius=5)
    }
    bites = CircularPattern(bite, 12, (0, 0))
    drawing words {
        ring = Circle(center=(0, 0), radius=39, construction=true)
        t = Text("SNOW BASKET", along=ring, size=3.5)
    }
}

assembly pair {
    left = basket()
    right = basket()
    RightOf(right, left, gap=6)
    AlignCenterY(right, left)

    # the request's numbers
    assert left.disc.diameter == 100 mm, "disc 100 across"
    assert left.bore.c.diameter == 10 mm, "10 mm bore"
    assert len(left.grip.l) == 6, "six grip slits"
    assert left.grip.l[0].end.x - left.bore.c.radius == 5 mm, "slits 5 mm past the bore"
    assert len(left.windows) == 6 and len(left.bites) == 12, "6 windows, 12 bites"
    assert left.window.w.width == 14 mm and (left.window.w.radius + left.window.w.inner_radius) / 2 == 30 mm,
        "windows on R30, 14 wide"
    assert left.bite.b.radius == 5 mm, "R5 bites"
}
