# Request (electronics): a soldering-iron stand from 3 mm plywood, glued.
# Base 160 x 120 mm with 6 mm rounded corners. The iron lies along the base's length, tip to
# the left, its axis 25 mm behind the base's middle line. Two uprights 60 mm wide stand
# across the base on two 15 mm tabs each (glued into mortises): the front (handle) upright
# 45 mm tall, 50 mm right of the middle, with a 22 mm wide U-notch whose bottom is 20 mm
# above the base; the back (barrel) upright 65 mm tall, 10 mm left of the middle, with a
# 12 mm U-notch whose bottom is 49 mm up, so the iron leans about 26 degrees.
# A sponge frame 60 x 45 mm with a 48 x 33 mm opening is glued on the base in the front-left
# corner, 10 mm in from the left and front edges. "HOT" engraved in 12 mm filled bold letters
# in the front-right corner and "SOLDER STATION" in 5 mm strokes along the front edge.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
axis_y = 25 mm
front_x = 50 mm
back_x = -10 mm
up_w = 60 mm

def upright(h=45 mm, notch_w=22 mm, notch_bottom=20 mm) -> solid {
    body = Rectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=h)
    feet = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole notch {
        # notch_bottom is measured from the base's top, i.e. from the tabs' shoulders (y = t)
        round = Circle(center=(0, t + notch_bottom + notch_w / 2), diameter=notch_w)
        mouth = Rectangle(bottom_left=(-notch_w / 2, t + notch_bottom + notch_w / 2), width=notch_w,
                          height=h - t - notch_bottom - notch_w / 2 + 1 mm)
    }
}

assembly stand {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=160, height=120, corner_radius=6)
        front_mortise = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15 mm,
                                     screw=0, rotation=90 deg, cx=front_x, cy=axis_y)
        back_mortise = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, rotation=90 deg, cx=back_x, cy=axis_y)
        drawing hot {
            word = Text("HOT", position=(50, -35), size=12, font="sans:Bold", valign="middle",
                        fill=true)
        }
        drawing title {
            line = Text("SOLDER STATION", position=(0, -54), size=5, valign="middle")
        }
        Fixed(body)
    }
    front = upright(h=45 mm, notch_w=22 mm, notch_bottom=20 mm)
    back = upright(h=65 mm, notch_w=12 mm, notch_bottom=49 mm)
    solid sponge {
        frame = Rectangle(center=(0, 0), width=60, height=45)
        hole well { r = Rectangle(center=(0, 0), width=48, height=33) }
    }

    # on the sheet: the small parts to the right of the base
    RightOf(front, base, gap=10)
    AlignTop(front, base)
    RightOf(back, front, gap=10)
    AlignTop(back, front)
    Below(sponge, front, gap=10)
    AlignLeft(sponge, front)

    # assembled: uprights stood across the base (local x -> world y, local y -> up)
    Place(base, position=(0, 0, 0))
    Place(front, rotation=(90 deg, 0, 90 deg), position=(front_x - t / 2, axis_y, 0))
    Place(back, rotation=(90 deg, 0, 90 deg), position=(back_x - t / 2, axis_y, 0))
    Place(sponge, position=(-80 mm + 10 mm + 30 mm, -60 mm + 10 mm + 22.5 mm, t))

    # the request's numbers
    assert base.body.width == 160 mm and base.body.height == 120 mm, "base 160 x 120"
    assert front.body.height == 45 mm and back.body.height == 65 mm, "upright heights"
    assert front.notch.round.bb.bottom - (front.body.bb.bottom + t) == 20 mm, "handle notch bottom 20 above the base"
    assert back.notch.round.bb.bottom - (back.body.bb.bottom + t) == 49 mm, "barrel notch bottom 49 up"
    assert front.notch.round.diameter == 22 mm and back.notch.round.diameter == 12 mm, "notch widths"
    assert abs(atan2(49 mm - 20 mm, front_x - back_x) - 26 deg) < 1 deg, "iron leans about 26 degrees"
    assert sponge.well.r.width == 48 mm and sponge.well.r.height == 33 mm, "sponge opening"
}
