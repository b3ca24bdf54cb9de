# Request (electronics): a split cable-entry clamp for the back of a 3D printer's electronics
# box, 3 mm acrylic. The plate is 100 x 50 mm overall (R4 outer corners), split along its
# horizontal middle into a top and a bottom half, each 100 x 25. Four round passages centred on
# the split, for cables of 5, 5, 7 and 9 mm (X, Y, Z motor leads and the PSU lead), cut 0.5 mm
# under each cable's size so the screwed halves grip; their centres 18, 38, 60 and 82 mm from
# the left edge. Four M3 holes 6 mm in from the plate's corners (two in each half). Behind it a
# 3 mm acrylic spacer frame of the same outline with a 76 x 30 window (R3) and the same four M3
# holes. Engraved on the top half above each passage: X, Y, Z, PSU (4 mm letters).

units mm
thickness 3 mm
import "std/fasteners.aidl"

cables = [5 mm, 5 mm, 7 mm, 9 mm]
xs = [18 mm, 38 mm, 60 mm, 82 mm]
names = ["X", "Y", "Z", "PSU"]

def half(top=true) -> solid {
    body = RoundedRectangle(bottom_left=(0, 25 if top else 0), width=100, height=25,
                            corner_radii=[4, 4, 0, 0] if top else [0, 0, 4, 4])
    hole passages {
        for i in range(4) {
            c = Circle(center=(xs[i], 25), diameter=cables[i] - 0.5 mm)
        }
    }
    m1 = clearance_hole(size=3, cx=6, cy=44 if top else 6)
    m2 = clearance_hole(size=3, cx=94, cy=44 if top else 6)
    if top {
        drawing labels {
            for i in range(4) {
                t = Text(names[i], position=(xs[i], 37), size=4, valign="middle")
            }
        }
    }
}

assembly cable_clamp {
    upper = half(top=true)
    lower = half(top=false)
    solid frame {
        body = RoundedRectangle(bottom_left=(0, 0), width=100, height=50, corner_radius=4)
        hole window { w = RoundedRectangle(center=(50, 25), width=76, height=30, corner_radius=3) }
        m = clearance_hole(size=3)
        CornerPattern(m, body, inset=6)
    }
    RightOf(frame, upper, gap=10)
    AlignBottom(frame, lower)

    # on the box wall: the frame against it, the two halves in front
    Place(frame, position=(0, 0, 0), face="front", up="up")
    Place(upper, position=(0, -3, 0), face="front", up="up")
    Place(lower, position=(0, -3, 0), face="front", up="up")

    assert upper.body.bb.width == 100 mm and upper.body.bb.height == 25 mm, "top half 100 x 25"
    assert lower.body.bb.width == 100 mm and lower.body.bb.height == 25 mm, "bottom half 100 x 25"
    assert upper.body.bb.top - lower.body.bb.bottom == 50 mm, "50 mm tall together"
    assert frame.body.bb.width == 100 mm and frame.body.bb.height == 50 mm, "frame the same outline"
    assert frame.window.w.width == 76 mm and frame.window.w.height == 30 mm, "76 x 30 window"
    assert len(upper.passages.c) == 4, "four passages"
    assert upper.passages.c[3].diameter == 9 mm - 0.5 mm, "PSU lead 9 mm, 0.5 under"
    assert upper.passages.c[0].diameter == 5 mm - 0.5 mm, "X lead 5 mm, 0.5 under"
    assert upper.passages.c[2].center.x - upper.body.bb.left == 60 mm, "Z passage 60 mm in"
    assert upper.passages.c[0].center.y == upper.body.bb.bottom, "passages centred on the split"
    assert upper.m1.c.center.x - upper.body.bb.left == 6 mm, "M3 6 mm in from the side"
    assert upper.body.bb.top - upper.m1.c.center.y == 6 mm, "M3 6 mm down from the top"
    assert lower.m1.c.center.y - lower.body.bb.bottom == 6 mm, "M3 6 mm up from the bottom"
    assert frame.m.c.center.x - frame.body.bb.left == 6 mm, "frame's M3 6 mm in"
}
