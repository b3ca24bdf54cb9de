# Request (gifts): a spectacles case as a birthday present, in 3 mm birch ply: a rounded box
# whose wall bends round living hinges, with a lift-off lid. Inside 160 x 62 x 42 mm (the
# folded glasses are 150 x 55 x 38), inner corner radius 20 mm, 0.3 mm clearance on the
# lid's lip. The lid carries the initials "E.R.W." (serif bold, 14 mm, filled) in the
# middle of an engraved oval 100 x 40 mm, both centred on the lid.

units mm
t = 3 mm
thickness t

import "std/boxes.aidl"

assembly glasses_case {
    case = flex_box(length=160 mm, width=62 mm, height=42 mm, radius=20 mm, thickness=t,
                    clearance=0.3 mm, outside=false)
    drawing monogram {
        oval = Ellipse(center=(0, 0), rx=50, ry=20)
        initials = Text("E.R.W.", position=(0, 0), size=14, font="serif:Bold",
                        valign="middle", fill=true)
    }
    CenterInside(monogram, case.lid)
    CutInto(monogram, case.lid)

    assert case.length == 160 mm and case.width == 62 mm and case.height == 42 mm,
        "inside 160 x 62 x 42"
    assert case.length - 150 mm >= 5 mm and case.width - 55 mm >= 5 mm and
        case.height - 38 mm >= 3 mm, "the folded glasses fit"
    assert monogram.oval.rx * 2 == 100 mm and monogram.oval.ry * 2 == 40 mm, "oval 100 x 40"
    assert monogram.initials.bb.width <= 100 mm - 16 mm, "initials inside the oval"
}
