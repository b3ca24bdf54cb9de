# Request (sport): a pool-side lap counter, cut from 3 mm acrylic, bolted with two M4 bolts.
# - Front plate 150 x 110 mm, 8 mm corner radius: two windows 14 wide x 16 tall side by side,
#   95 mm apart, that show one digit each of two number wheels behind; "LAPS" engraved 8 mm tall
#   above the windows, "TENS" and "ONES" 4 mm tall under them; 4.3 mm pivot holes for the wheels,
#   35 mm below each window's centre.
# - Two number wheels 90 mm across with the digits 0-9 engraved 10 mm tall round a 30 mm circle
#   (each upright when it stands at the top, in the window) and 20 thumb scallops (6 mm round
#   notches) round the rim; the wheels stick out past the plate's sides for the thumbs.
# - Back plate the same outline as the front, the same pivot holes, and a 20 x 5 mm lanyard slot
#   12 mm below the top edge.

thickness 3 mm

param apart = 95 mm, min = 92 mm, max = 110 mm
param drop = 35 mm, min = 30 mm, max = 40 mm

def wheel() -> solid {
    disc = Circle(center=(0, 0), diameter=90)
    hole pivot { c = Circle(center=(0, 0), diameter=4.3) }
    hole grip { g = Circle(center=(45, 0), diameter=6) }
    grips = CircularPattern(grip, 20, (0, 0))
    drawing digits {
        ring = Circle(center=(0, 0), radius=30, construction=true)
        for i in range(10) {
            d = Text(str(i), along=ring, angle=90 deg - i * 36 deg, size=10)
        }
    }
}

def plate_outline() -> solid {
    body = RoundedRectangle(center=(0, 0), width=150, height=110, corner_radius=8)
    hole pivots {
        l = Circle(center=(-apart / 2, 25 - drop), diameter=4.3)
        r = Circle(center=(apart / 2, 25 - drop), diameter=4.3)
    }
}

assembly lap_counter {
    solid front {
        p = plate_outline()
        hole windows {
            tens = Rectangle(center=(-apart / 2, 25), width=14, height=16)
            ones = Rectangle(center=(apart / 2, 25), width=14, height=16)
        }
        drawing labels {
            title = Text("LAPS", (0, 40), size=8, valign="middle")
            t = Text("TENS", (-apart / 2, 10), size=4, valign="middle")
            o = Text("ONES", (apart / 2, 10), size=4, valign="middle")
        }
    }

    solid back {
        p = plate_outline()
        hole lanyard { s = Slot(center=(0, 55 - 12), length=20, width=5) }
    }

    tens = wheel()
    ones = wheel()

    # laid out flat for cutting
    RightOf(back, front, gap=8)
    AlignCenterY(back, front)
    Below(tens, front, gap=8)
    AlignLeft(tens, front)
    RightOf(ones, tens, gap=8)
    AlignCenterY(ones, tens)
    # stacked in 3D: back, wheels, front
    Place(back, position=(0, 0, 0))
    Place(tens, position=(-apart / 2, 25 - drop, 3))
    Place(ones, position=(apart / 2, 25 - drop, 3))
    Place(front, position=(0, 0, 6))

    # the request's numbers
    assert front.p.body.bb.width == 150 mm and front.p.body.bb.height == 110 mm, "150 x 110"
    assert front.windows.ones.center.x - front.windows.tens.center.x == 95 mm, "windows 95 apart"
    assert front.windows.ones.center.y - front.p.pivots.r.center.y == 35 mm, "pivot 35 below"
    assert front.windows.ones.width == 14 mm and front.windows.ones.height == 16 mm, "14 x 16"
    assert tens.disc.diameter == 90 mm, "wheels 90 across"
    assert len(tens.grips) == 20, "20 scallops"
    assert len(tens.digits.d) == 10, "ten digits"
    assert 90 mm / 2 > 150 mm / 2 - 95 mm / 2, "wheels stick out past the sides"
    assert back.p.body.bb.top - back.lanyard.s.center.y == 12 mm, "lanyard 12 below the top"
}
