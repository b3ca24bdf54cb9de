# Request (toys): a bolt-together construction kit for my nephew, Meccano sizes, from
# 4 mm birch ply, for M4 nuts and bolts: every hole 4.2 mm at the half-inch pitch
# (12.7 mm). One of each, I cut more as needed:
# - perforated strips 12.7 mm wide with round ends, of 5, 7 and 11 holes (a strip is its
#   hole count times 12.7 long, the end holes at the end arcs' centres);
# - a flat plate of 5 x 3 holes, 63.5 x 38.1 mm, R3 corners;
# - a 63.5 mm wheel: a centre hole, 4 bolt holes on a 25.4 mm circle (at 0, 90, 180, 270
#   deg), and 4 window openings between them (19 to 26 mm radius, 60 deg wide, R2);
# - "BUILD-IT" engraved (single line) on the plate, between its top two rows of holes.
# Kerf of my laser: 0.15 mm.

units mm
thickness 4 mm
kerf 0.15 mm

pitch = 12.7 mm
bolt = 4.2 mm

def strip(n=5) -> solid {
    body = Slot(center=(0, 0), length=n * pitch, width=pitch)
    hole h { c = Circle(center=(-(n - 1) * pitch / 2, 0), diameter=bolt) }
    row = LinearPattern(h, n, (pitch, 0))
}

assembly kit {
    s11 = strip(11)
    s7 = strip(7)
    s5 = strip(5)

    solid plate {
        body = RoundedRectangle(center=(0, 0), width=5 * pitch, height=3 * pitch,
                                corner_radius=3)
        hole h { c = Circle(center=(-2 * pitch, -pitch), diameter=bolt) }
        grid = GridPattern(h, 3, 5, (pitch, pitch))
        drawing name {
            word = Text("BUILD-IT", position=(0, pitch / 2), size=4, valign="middle")
        }
    }

    solid wheel {
        disc = Circle(center=(0, 0), diameter=63.5)
        hole axle { c = Circle(center=(0, 0), diameter=bolt) }
        hole b { c = Circle(center=(12.7, 0), diameter=bolt) }
        bolts = CircularPattern(b, 4, disc.center)
        hole win {
            w = Sector(center=(0, 0), radius=26, start_angle=15 deg, end_angle=75 deg,
                       inner_radius=19)
            Fillet(2)
        }
        windows = CircularPattern(win, 4, disc.center)
    }

    # flat on the sheet
    Below(s7, s11, gap=6)
    AlignLeft(s7, s11)
    Below(s5, s7, gap=6)
    AlignLeft(s5, s11)
    Below(plate, s5, gap=6)
    AlignLeft(plate, s11)
    RightOf(wheel, plate, gap=6)
    AlignTop(wheel, plate)

    # the request's numbers
    assert len(s11.row) == 11 and len(s7.row) == 7 and len(s5.row) == 5, "hole counts"
    assert s11.body.length == 11 * 12.7 mm and s11.body.width == 12.7 mm, "11-hole strip"
    assert s11.row[10].c.center.x - s11.row[0].c.center.x == 10 * 12.7 mm, "half-inch pitch"
    assert s11.body.bb.right - s11.row[10].c.center.x == 12.7 mm / 2, "end hole at the arc"
    assert len(plate.grid) == 15, "5 x 3 holes"
    assert plate.body.width == 63.5 mm and plate.body.height == 38.1 mm, "plate size"
    assert wheel.disc.diameter == 63.5 mm, "wheel 63.5"
    assert distance(wheel.bolts[1].c.center, wheel.disc.center) == 25.4 mm / 2,
        "bolt circle 25.4"
    assert len(wheel.windows) == 4, "4 windows"
}
