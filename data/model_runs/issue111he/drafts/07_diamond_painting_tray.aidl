# Request (crafts): a sorting tray for diamond-painting drills, two layers of 3 mm acrylic
# glued together, 100 x 70 mm with 8 mm round corners and a pouring spout at the top-right
# corner. The top layer is a rim: 4 mm wide on the left, top and right and 14 mm along the
# bottom (for a label), the window's corners rounded 5 mm, and a 7 mm channel through the
# rim at the spout so the drills pour out. The bottom layer is whole; its floor under the
# window is engraved with diagonal ridges 5 mm apart, which make the drills flip face up when
# the tray is shaken. On the label band: DMC engraved and a frosted (filled) write-on patch
# 50 x 8 mm.

thickness 3 mm

assembly drill_tray {
    solid rim {
        plate = RoundedRectangle(center=(0, 0), width=100, height=70, corner_radius=8)
        # FIX after the first valid program: Hull(plate, tip) skewed the whole outline into
        # a lopsided quadrilateral; the spout is now the hull of the corner's own rounding
        # circle and the tip, united with the plate
        tip = Circle(center=(54, 39), radius=3, construction=true)
        corner = Circle(center=(42, 27), radius=8, construction=true)
        spout = Hull(corner, tip)
        hole window {
            w = RoundedRectangle(center=(0, 5), width=92, height=52, corner_radius=5)
            channel = Slot(start=(40, 25), end=(60, 45), width=7)
        }
        drawing label {
            code = Text("DMC", position=(-36, -28), size=6, valign="middle")
            patch = Rectangle(center=(12, -28), width=50, height=8, fill=true)
        }
        assert plate.width == 100 mm and plate.height == 70 mm, "100 x 70"
        assert window.w.bb.left - plate.bb.left == 4 mm, "4 mm rim left"
        assert plate.bb.top - window.w.bb.top == 4 mm, "4 mm rim top"
        assert window.w.bb.bottom - plate.bb.bottom == 14 mm, "14 mm label band"
        assert distance(label, window) >= 2 mm, "label on the band"
        assert spout.bb.right - plate.bb.right <= 7 mm and spout.bb.top - plate.bb.top <= 7 mm,
            "only the spout sticks out"
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=100, height=70, corner_radius=8)
        # FIX after the first valid program: Hull(plate, tip) skewed the whole outline into
        # a lopsided quadrilateral; the spout is now the hull of the corner's own rounding
        # circle and the tip, united with the plate
        tip = Circle(center=(54, 39), radius=3, construction=true)
        corner = Circle(center=(42, 27), radius=8, construction=true)
        spout = Hull(corner, tip)
        drawing ridges {
            floor = RoundedRectangle(center=(0, 5), width=92, height=52, corner_radius=5,
                                     construction=true)
            for i in range(29) {
                l = Line((-98 + i * 5, -21), (-98 + i * 5 + 52, 31))
            }
            clipped = Intersect([floor] + l)
        }
        assert len(ridges.l) == 29, "ridges across the whole floor"
    }

    RightOf(base, rim, gap=10)
    AlignTop(base, rim)
}
