# Pets: a 3 mm acrylic lid for a small fish tank, 300 x 160 mm, 5 mm corner radius.
# A feeding hatch opening 60 x 40 mm (4 mm corner radius) whose centre is 70 mm left
# of the lid's centre and 45 mm in from the front (bottom) edge; "FEED" engraved 5 mm
# high, 6 mm below the hatch. Two cable notches in the back (top) edge, 10 mm wide and
# 8 mm deep, their centres 30 mm in from each end. A vent grid of 5 mm holes, 4 rows x
# 8 columns at 12 mm pitch, centred 70 mm right of the lid's centre.
thickness 3 mm

param rows = 4, min = 2, max = 6
param cols = 8, min = 4, max = 9

solid lid {
    plate = RoundedRectangle(center=(0, 0), width=300, height=160, corner_radius=5)

    hole hatch { r = RoundedRectangle(center=(-70, -35), width=60, height=40, corner_radius=4) }
    hatch.r.center.x == plate.center.x - 70 mm
    hatch.r.center.y == plate.bb.bottom + 45 mm

    drawing feed { t = Text("FEED", (-70, -65), size=5, valign="top") }
    AlignCenterX(feed, hatch)
    Below(feed, hatch, gap=6)

    hole notch { r = Rectangle(center=(-120, 78), width=10, height=12) }
    notches = LinearPattern(notch, 2, (240, 0))
    notch.r.center.x == plate.bb.left + 30 mm
    notch.r.bb.bottom == plate.bb.top - 8 mm

    hole vent { c = Circle(center=(28, -18), diameter=5) }
    grid = GridPattern(vent, rows, cols, 12)
    grid[0].c.center.x + grid[rows * cols - 1].c.center.x == 2 * (plate.center.x + 70 mm)
    grid[0].c.center.y + grid[rows * cols - 1].c.center.y == 2 * plate.center.y

    assert plate.width == 300 mm and plate.height == 160 mm, "lid 300 x 160"
    assert hatch.r.width == 60 mm and hatch.r.height == 40 mm, "hatch 60 x 40"
    assert hatch.r.center.y - plate.bb.bottom == 45 mm, "hatch 45 from the front"
    assert plate.bb.top - notch.r.bb.bottom == 8 mm, "notches 8 deep"
    assert plate.bb.right - notches[1].r.center.x == 30 mm, "right notch 30 in"
    assert len(grid) == 32, "4 x 8 vents"
    assert grid[1].c.center.x - grid[0].c.center.x == 12 mm, "12 mm pitch"
}
