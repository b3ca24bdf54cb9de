# Toy gear set for a wall-mounted busy board: a 15-tooth and a 30-tooth spur gear, module
# 3 mm, 0.15 mm backlash, 6 mm axle bores; the big gear has four 12 mm lightening holes on a
# 25 mm radius; a 130 x 50 mm base plate with 6 mm rounded corners and two 6 mm axle holes
# at the gears' center distance (67.5 mm), laid out 10 mm below the gears.

import "std/gears.aidl"

thickness 4 mm

assembly toy {
    pair = gear_pair(teeth1=15, teeth2=30, module=3 mm, bore1=6 mm, bore2=6 mm, backlash=0.15 mm)
    hole lighten {
        for i in range(4) {
            c = Circle(center=(67.5 + 25 * cos(i * 90 deg + 45 deg), 25 * sin(i * 90 deg + 45 deg)), diameter=12)
        }
    }
    CenterInside(lighten, pair.gear2)
    CutInto(lighten, pair.gear2)
    solid base {
        body = RoundedRectangle(center=(33.75, -80), width=130, height=50, corner_radius=6)
        hole axle {
            c = Circle(center=(0, -80), diameter=6)
        }
        right_axle = Translated(axle, (67.5, 0))
        AlignCenterY(axle, body)
        axle.c.center.x == body.center.x - 67.5 mm / 2
    }
    Below(base, pair, gap=10)
    AlignCenterX(base, pair)
    assert pair.center_distance == 67.5 mm, "center distance 67.5"
    assert distance(base.axle.c.center, base.right_axle.c.center) == pair.center_distance, "axle holes at the center distance"
    assert base.body.bb.width == 130 mm and base.body.bb.height == 50 mm, "130 x 50 plate"
    assert len(lighten.c) == 4, "four lightening holes"
}
