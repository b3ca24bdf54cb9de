# Request (signs): a "NOW SERVING" number sign for a deli counter's queue, hung on the wall;
# 3 mm plywood, the spacer 4 mm.
# - Front plate 360 x 240 mm, corners R10, NOW SERVING engraved filled (bold sans 24 mm)
#   centred 85 mm above the centre.
# - Two digit wheels 160 mm across turning on M5 pivot bolts 170 mm apart (85 either side
#   of the centre), 30 mm below the centre. Each wheel engraved filled with the digits 0 to
#   9 (bold sans 30 mm), their middles on radius 60, 36 deg apart, each upright when it is
#   at the top; 0 at the top as cut.
# - In the front plate: a window 40 x 44 mm (R4) centred 60 mm above each pivot, showing one
#   digit; under each pivot a finger slot along the wheel, 16 mm wide on radius 66 from
#   235 to 305 deg, to turn it.
# - A 4 mm spacer, the plate's outline with a 166 mm opening round each wheel.
# - A back plate, the plate's outline, with two keyholes for hanging 120 mm either side of
#   the centre and 80 mm above it.
# - Four M4 bolts through front, spacer and back at (+-165, +-105); M5 pivots 5.3 mm in
#   the plates, 5.8 mm in the wheels (they turn).

import "std/fasteners.aidl"
import "std/plates.aidl"

thickness 3 mm

pivot_x = [-85, 85]
pivot_y = -30

def outline_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=360, height=240, corner_radius=10)
    b = clearance_hole(size=4)
    bolts = CornerPattern(b, body, inset=15)
}

def digit_wheel() -> solid {
    disc = Circle(center=(0, 0), diameter=160)
    hole pivot { c = Circle(center=(0, 0), diameter=5.8) }
    drawing digits {
        ring = Circle(center=(0, 0), radius=60, construction=true)
        for k in range(10) {
            d = Text(str(k), along=ring, angle=90 deg - k * 36 deg, size=30,
                     font="sans:Bold", valign="middle", fill=true)
        }
    }
}

assembly sign {
    front = outline_plate()
    hole front_cuts {
        wl = RoundedRectangle(center=(-85, 30), width=40, height=44, corner_radius=4)
        wr = RoundedRectangle(center=(85, 30), width=40, height=44, corner_radius=4)
        pl = Circle(center=(-85, -30), diameter=5.3)
        pr = Circle(center=(85, -30), diameter=5.3)
        fl = ArcSlot(center=(-85, -30), radius=66, start_angle=235 deg, end_angle=305 deg,
                     width=16)
        fr = ArcSlot(center=(85, -30), radius=66, start_angle=235 deg, end_angle=305 deg,
                     width=16)
    }
    CutInto(front_cuts, front)
    drawing title {
        t = Text("NOW SERVING", position=(0, 85), size=24, font="sans:Bold",
                 valign="middle", fill=true)
    }
    CutInto(title, front)

    spacer = outline_plate()
    hole spacer_cuts {
        open_l = Circle(center=(-85, -30), diameter=166)
        open_r = Circle(center=(85, -30), diameter=166)
    }
    CutInto(spacer_cuts, spacer)

    back = outline_plate()
    hole back_cuts {
        pl = Circle(center=(-85, -30), diameter=5.3)
        pr = Circle(center=(85, -30), diameter=5.3)
    }
    CutInto(back_cuts, back)
    hang_l = keyhole(cx=-120 mm, cy=80 mm)
    hang_r = keyhole(cx=120 mm, cy=80 mm)
    CutInto(hang_l, back)
    CutInto(hang_r, back)

    wheel_l = digit_wheel()
    wheel_r = digit_wheel()

    # flat on the sheet: all cut-outs placed with their plates
    Rigid(front, front_cuts, title)
    Rigid(spacer, spacer_cuts)
    Rigid(back, back_cuts, hang_l, hang_r)
    RightOf(spacer, front, gap=10)
    AlignTop(spacer, front)
    Below(back, front, gap=10)
    AlignLeft(back, front)
    RightOf(wheel_l, back, gap=10)
    AlignTop(wheel_l, back)
    RightOf(wheel_r, wheel_l, gap=10)
    AlignTop(wheel_r, wheel_l)

    # in 3D: the wall at y = 0, the back plate against it, then spacer, wheels, front
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(spacer, position=(0, -3, 0), face="front", up="up")
    Place(wheel_l, position=(-85, -3, -30), face="front", up="up")
    Place(wheel_r, position=(85, -3, -30), face="front", up="up")
    Place(front, position=(0, -7, 0), face="front", up="up")

    assert front.body.bb.width == 360 mm and front.body.bb.height == 240 mm, "360 x 240"
    assert front_cuts.pr.center.x - front_cuts.pl.center.x == 170 mm, "pivots 170 apart"
    assert front_cuts.wl.center.y - front_cuts.pl.center.y == 60 mm, "window 60 above the pivot"
    assert front_cuts.wl.width == 40 mm and front_cuts.wl.height == 44 mm, "40 x 44 windows"
    assert wheel_l.disc.diameter == 160 mm, "160 mm wheels"
    assert len(wheel_l.digits.d) == 10, "digits 0 to 9"
    assert spacer_cuts.open_l.diameter == 166 mm, "166 mm openings"
    assert hang_r.head_hole.center.x - hang_l.head_hole.center.x == 240 mm, "keyholes 120 either side"
    assert title.t.position.y - front.body.center.y == 85 mm, "title 85 above the centre"
    assert distance(title.t, front_cuts.wl) >= 5 mm, "title clear of the windows"
}
