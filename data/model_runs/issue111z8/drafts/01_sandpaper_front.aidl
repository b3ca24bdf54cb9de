# Workshop: the front panel of a wall-mounted sandpaper sorter, 3 mm birch ply.
# Panel 240 x 100 mm with 5 mm corner radius. Five compartments 46 mm apart
# (centres at x = -92, -46, 0, 46, 92 from the panel's centre); above each a
# finger-dip notch in the top edge: a half circle of 15 mm radius. Under each
# notch the grit engraved, 8 mm tall, its baseline 35 mm below the top edge:
# "80", "120", "180", "240", "320". Two 4.5 mm screw holes countersunk for 9 mm
# flat heads, 12 mm above the bottom edge and 20 mm in from each side.

units mm
thickness 3 mm

grits = ["80", "120", "180", "240", "320"]
pitch = 46 mm

solid front {
    panel = RoundedRectangle(center=(0, 0), width=240, height=100, corner_radius=5)

    hole dips {
        for i in range(5) {
            d = Circle(center=((i - 2) * pitch, 50), radius=15)
        }
    }

    drawing labels {
        for i in range(5) {
            t = Text(grits[i], position=((i - 2) * pitch, 50 - 35), size=8)
        }
    }

    hole screw {
        c = Circle(center=(-100, -38), diameter=4.5)
    }
    other = Mirrored(screw, about=Line((0, -60), (0, 60), construction=true))
    Countersink([screw, other], diameter=9)

    assert panel.width == 240 mm and panel.height == 100 mm, "panel 240 x 100"
    assert len(dips.d) == 5, "five finger dips"
    assert dips.d[1].center.x - dips.d[0].center.x == 46 mm, "compartments 46 apart"
    assert dips.d[2].center.y == panel.bb.top, "dips centred on the top edge"
    assert dips.d[0].radius == 15 mm, "dip radius 15"
    assert panel.bb.top - labels.t[0].position.y == 35 mm, "labels' baseline 35 below the top"
    assert screw.c.center.y - panel.bb.bottom == 12 mm, "screws 12 above the bottom"
    assert screw.c.center.x - panel.bb.left == 20 mm, "screws 20 in from the side"
    assert panel.bb.right - other.c.center.x == 20 mm, "other screw 20 in from the side"
}
