# Garden plant marker: a stake 25 mm wide and 150 mm long overall, whose bottom
# 30 mm taper to a point; the top corners rounded R4; "BASIL" engraved 8 mm high
# centered on the 120 mm straight part, 20 mm below the top.
thickness 3 mm

param width = 25 mm, min = 15 mm, max = 40 mm
param length = 150 mm, min = 100 mm, max = 250 mm
param tip = 30 mm, min = 15 mm, max = 50 mm

solid marker {
    top = RoundedRectangle(center=(0, (length - tip) / 2), width=width, height=length - tip,
                           corner_radii=[4, 4, 0, 0])
    point = Triangle(center=(0, -tip / 2), base=width, height=tip, rotation=180 deg)
    Above(top, point)
    AlignCenterX(point, top)

    drawing label {
        word = Text("BASIL", (0, 0), size=8, valign="middle", max_width=21 mm)
    }
    AlignCenterX(label, top)
    label.word.position.y == top.bb.top - 20 mm
}

assert marker.top.bb.width == 25 mm, "25 mm wide"
assert marker.top.bb.top - marker.point.bb.bottom == 150 mm, "150 mm long overall"
assert marker.top.bb.height == 120 mm, "straight part 120 mm"
assert marker.point.bb.height == 30 mm, "30 mm taper"
assert marker.top.bb.top - marker.label.word.position.y == 20 mm, "label 20 mm below the top"
