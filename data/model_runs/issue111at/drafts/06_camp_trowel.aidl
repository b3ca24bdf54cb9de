# Request (camping): a flat backcountry trowel laser-cut from 1.5 mm stainless steel, 180 mm long
# from the blade's tip to the end of the handle. The blade is a pointed shield 60 mm wide across
# its top (the hull of a 4 mm-radius rounded tip and two 4 mm-radius top corners 90 mm up, 52 mm
# apart), the handle 28 mm wide rising from the blade to a fully rounded end. The handle has three
# 16 x 8 mm lightening slots (centres 110, 130 and 150 mm from the tip) and an 8 mm lanyard hole
# 12 mm from its end. The blade's right edge has six root-cutting notches (5 mm wide at the
# edge, 2.5 mm deep, 7 mm apart) between 40 and 80 mm up, and engraved depth marks: 8 mm lines
# across the middle at 4, 6 and 8 cm from the tip, each labelled with its number of cm.

thickness 1.5 mm

param blade_w = 60 mm, min = 50 mm, max = 70 mm
param handle_w = 28 mm, min = 22 mm, max = 34 mm

# the blade's right edge: from the tip circle (0, 4) to the corner circle (26, 90), both r 4
half = blade_w / 2 - 4 mm
elen = sqrt(half ** 2 + 86 mm ** 2)
ux = half / elen
uy = 86 mm / elen
nx = uy
ny = -ux
ex0 = 4 * nx
ey0 = 4 mm + 4 * ny

solid trowel {
    solid blade {
        tip = Circle(center=(0, 4), radius=4)
        left_c = Circle(center=(-half, 90), radius=4)
        right_c = Circle(center=(half, 90), radius=4)
        shield = Hull(tip, left_c, right_c)
    }
    solid handle {
        grip = RoundedRectangle(center=(0, 135), width=handle_w, height=90,
                                corner_radii=[handle_w / 2, handle_w / 2, 0, 0])
    }
    for i in range(3) {
        hole lighten {
            s = Slot(center=(0, 110 + 20 * i), length=16, width=8, rotation=90 deg)
        }
    }
    hole lanyard {
        c = Circle(center=(0, 168), diameter=8)
    }
    for i in range(6) {
        hole notch {
            n = Triangle((ex0 + (40 + 7 * i) * ux + 1 * nx, ey0 + (40 + 7 * i) * uy + 1 * ny),
                         (ex0 + (45 + 7 * i) * ux + 1 * nx, ey0 + (45 + 7 * i) * uy + 1 * ny),
                         (ex0 + (42.5 + 7 * i) * ux - 2.5 * nx, ey0 + (42.5 + 7 * i) * uy - 2.5 * ny))
        }
    }
    drawing depth {
        for k in range(3) {
            tick = Line((-4, 40 + 20 * k), (4, 40 + 20 * k))
            num = Text(str(4 + 2 * k), position=(6, 40 + 20 * k), size=4, anchor="start",
                       valign="middle")
        }
    }

    assert abs(blade.shield.bb.width - 60 mm) < 0.01 mm, "blade 60 wide"
    assert abs(handle.grip.bb.top - blade.shield.bb.bottom - 180 mm) < 0.01 mm, "180 long overall"
    assert handle.grip.bb.width == 28 mm, "handle 28 wide"
    assert len(lighten) == 3 and len(notch) == 6, "three slots, six notches"
    assert abs(handle.grip.bb.top - lanyard.c.center.y - 12 mm) < 0.01 mm, "lanyard 12 from the end"
    assert lanyard.c.diameter == 8 mm, "lanyard 8"
    assert depth.tick[0].start.y - blade.shield.bb.bottom == 40 mm, "first mark 4 cm from the tip"
    assert depth.tick[2].start.y - blade.shield.bb.bottom == 80 mm, "last mark 8 cm from the tip"
    assert depth.tick[0].length == 8 mm, "marks 8 long"
    assert notch[0].n.bb.bottom > blade.shield.bb.bottom + 40 mm - 1 mm, "notches start 40 up"
}
