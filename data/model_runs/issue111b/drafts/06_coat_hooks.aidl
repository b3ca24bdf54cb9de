# Wall coat-hook rail, 6 mm birch plywood: a backplate 140 x 50 mm with R6 corners, two
# 4.5 mm screw holes on its center line 15 mm from each end, countersunk 9 mm (90 deg) for
# M4 flat heads; three mortises 6.2 x 20 mm (20 mm upright) centered at x = -35, 0, +35 mm.
# Three hooks, each a flat profile: a tenon 6 mm long x 20 mm tall (goes through the plate),
# an arm 45 mm long x 28 mm tall centered on the tenon (4 mm shoulders above and below),
# and an upright round-topped post at the arm's end, 14 mm wide, rising 37 mm above the
# tenon's center line. Parts laid out 5 mm apart.

units mm
thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm
param spacing = 35 mm, min = 25 mm, max = 45 mm

def hook_part() -> solid {
    tenon = Rectangle(bottom_left=(-6, -10), width=t, height=20)
    arm = Rectangle(bottom_left=(0, -14), width=45, height=28)
    post = Slot(start=(38, 0), end=(38, 30), width=14)
}

assembly coat_hooks {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=140, height=50, corner_radius=6)
        hole screws {
            left = Circle(center=(-55, 0), diameter=4.5)
            right = Circle(center=(55, 0), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        hole mortise {
            for i in range(3) {
                m = Rectangle(center=((i - 1) * spacing, 0), width=t + 0.2 mm, height=20)
            }
        }
        assert abs(body.bb.width - 140 mm) < 0.001 mm and abs(body.bb.height - 50 mm) < 0.001 mm, "plate 140 x 50"
        assert abs(screws.left.center.x - body.bb.left - 15 mm) < 0.001 mm, "screw 15 mm from the end"
        assert abs(mortise.m[2].center.x - mortise.m[1].center.x - 35 mm) < 0.001 mm, "mortises 35 mm apart"
        assert abs(mortise.m[0].width - 6.2 mm) < 0.001 mm, "mortise 6.2 mm wide"
    }

    h1 = hook_part()
    h2 = hook_part()
    h3 = hook_part()
    Below(h1, plate, gap=5 mm)
    AlignLeft(h1, plate)
    RightOf(h2, h1, gap=5 mm)
    AlignBottom(h2, h1)
    RightOf(h3, h2, gap=5 mm)
    AlignBottom(h3, h1)

    assert abs(h1.tenon.height - 20 mm) < 0.001 mm and abs(h1.tenon.width - 6 mm) < 0.001 mm, "tenon 6 x 20"
    assert abs(h1.arm.width - 45 mm) < 0.001 mm and abs(h1.arm.height - 28 mm) < 0.001 mm, "arm 45 x 28"
    assert abs(h1.post.bb.top - h1.tenon.center.y - 37 mm) < 0.001 mm, "post tip 37 mm above the tenon's center line"
    assert abs(h1.post.width - 14 mm) < 0.001 mm, "post 14 mm wide"
}
