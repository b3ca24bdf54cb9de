# Bathroom: an upside-down bottle holder for the shower, 6 mm acrylic, screwed flat under a
# wall shelf. A plate 240 x 90 mm with R6 corners; 3 neck holes 36 mm across, 75 mm apart,
# their centres 45 mm from the back edge (on the plate's middle line), each opened to the
# front edge by a channel 26 mm wide; every corner the channels make rounded R3. 4 screw
# holes 4.5 mm countersunk 9 mm, 12 mm from the back edge, at x = -105, -37.5, 37.5, 105 mm.
# A single-stroke label 4 mm tall over each neck hole: SHAMPOO, CONDITIONER, GEL.
thickness 6 mm

necks = ["SHAMPOO", "CONDITIONER", "GEL"]
neck_d = 36 mm
channel_w = 26 mm
pitch = 75 mm
screw_x = [-105 mm, -37.5 mm, 37.5 mm, 105 mm]

solid shelf {
    plate = RoundedRectangle(center=(0, 0), width=240, height=90, corner_radius=6)

    hole neck {
        for i in range(3) {
            c = Circle(center=((i - 1) * pitch, 0), diameter=neck_d)
            ch = Rectangle(center=((i - 1) * pitch, -22.5), width=channel_w, height=45)
            run = Rectangle(center=((i - 1) * pitch, -46), width=channel_w, height=2, overrun=true)
        }
    }

    hole screw {
        for x in screw_x {
            c = Circle(center=(x, 45 - 12), diameter=4.5)
        }
    }
    Countersink(screw, diameter=9)

    drawing labels {
        for i in range(3) {
            t = Text(necks[i], position=((i - 1) * pitch, 24), size=4, valign="middle")
        }
    }

    Fillet(3)

    assert plate.bb.width == 240 mm and plate.bb.height == 90 mm, "plate 240 x 90"
    assert len(neck.c) == 3, "3 neck holes"
    assert neck.c[0].diameter == 36 mm, "necks 36 across"
    assert neck.c[1].center.x - neck.c[0].center.x == 75 mm, "75 apart"
    assert plate.bb.top - neck.c[0].center.y == 45 mm, "neck centres 45 from the back"
    assert neck.ch[0].width == 26 mm, "channels 26 wide"
    assert len(screw.c) == 4, "4 screws"
    assert plate.bb.top - screw.c[0].center.y == 12 mm, "screws 12 from the back"
}
