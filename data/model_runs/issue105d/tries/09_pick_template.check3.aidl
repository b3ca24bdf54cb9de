# Guitar-pick template: a 130 x 70 mm plate (5 mm rounded corners) with three
# pick-shaped cut-outs side by side, centres 40 mm apart and centred on the plate:
# small (0.85x), medium (26 x 30 mm) and large (1.15x); each labelled "S", "M", "L"
# engraved 5 mm tall, 6 mm below its pick.
param scale_s = 0.85, min = 0.7, max = 0.95
param scale_l = 1.15, min = 1.05, max = 1.3
thickness 1 mm

def pick() -> hole {
    top_l = Circle(center=(-8, 5), radius=5)
    top_r = Circle(center=(8, 5), radius=5)
    tip = Circle(center=(0, -17.5), radius=2.5)
    outline = Hull(top_l, top_r, tip)
}

solid template {
    plate = RoundedRectangle(center=(0, 0), width=130, height=70, corner_radius=5)
    small = pick()
    medium = pick()
    large = pick()
    Rigid(small)
    Rigid(medium)
    Rigid(large)
    Scale(small, scale_s)
    Scale(large, scale_l)
    medium.bb.center_y == plate.center.y + 5
    AlignCenterY(small, medium)
    AlignCenterY(large, medium)
    medium.bb.center_x == plate.center.x
    small.bb.center_x == medium.bb.center_x - 40
    large.bb.center_x == medium.bb.center_x + 40
    drawing labels {
        s = Text("S", (-40, -25), size=5, valign="top")
        m = Text("M", (0, -25), size=5, valign="top")
        l = Text("L", (40, -25), size=5, valign="top")
    }
    At(labels.s.position, (small.bb.center_x, small.bb.bottom - 6))
    At(labels.m.position, (medium.bb.center_x, medium.bb.bottom - 6))
    At(labels.l.position, (large.bb.center_x, large.bb.bottom - 6))
    assert medium.bb.width == 26 mm and medium.bb.height == 30 mm, "medium pick 26 x 30"
    assert labels.bb.bottom > plate.bb.bottom + 2 mm, "labels on the plate"
    assert large.bb.right < plate.bb.right - 3 mm, "large pick inside"
}
