# Request: a fruit picker head for a 25 mm broom handle, 6 mm exterior ply, glued.
# A basket 130 mm wide (outside, across) and 130 mm front to back (outside the front
# and back panels). Back panel 150 mm tall with five tines on top, 55 mm tall, at
# 26 mm pitch (each 14 mm wide at its root, 8 mm at its tip, so the stem slides down
# into a narrowing gap); front panel 80 mm tall with five 40 mm tines the same
# way. The side panels run 10 mm past the front and back faces and slope from the
# front's 80 mm to the back's 150 mm; the front and back have two 25 mm tenons
# through each side; the bottom (its underside 10 mm up) has two 25 mm tenons into
# each of the four walls and four 10 mm rain holes. On the back's outside two
# 60 x 50 mm brackets with one 30 mm tenon each: the lower one (underside 20 mm
# up) with a 26 mm hole for the pole, centred 25 mm off the back; the upper one
# (underside 120 mm up) stops the pole's end and takes an M5 countersunk screw into it.
# FIX after the first valid program: the bottom's front and back tenons were turned the
# wrong way (W0502, W0517: rotation 0 at the front edge, 180 at the back: swapped); the
# tines now stand on the wall's top edge instead of overlapping it by 1 mm (W0520: a
# 0.07 mm ledge against the end of the side tenons' notch); the brackets are laid out
# beside the back on the flat drawing (W0511).

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/fasteners.aidl"

T = 6 mm
W = 130 mm
D = 130 mm
HB = 150 mm
HF = 80 mm
OVER = 10 mm     # sides past the front and back faces
ZB = 10 mm       # underside of the bottom
PITCH = 26 mm
BR_D = 50 mm     # bracket depth off the back
POLE_OFF = 25 mm

# front or back wall, drawn from outside: x across, y up
def wall(h=80 mm, tine_h=40 mm) -> solid {
    body = Rectangle(bottom_left=(-W / 2, 0), width=W, height=h)
    tine = Trapezoid(center=(-2 * PITCH, h + tine_h / 2), bottom_width=14, top_width=8,
                     height=tine_h)
    tines = LinearPattern(tine, 5, (PITCH, 0))
    left_tenons = tab_and_slot(part="tab", length=h, thickness=T, tabs=2, tab=25 mm, screw=0,
                               rotation=90 deg, cx=-W / 2, cy=h / 2)
    right_tenons = tab_and_slot(part="tab", length=h, thickness=T, tabs=2, tab=25 mm, screw=0,
                                rotation=-90 deg, cx=W / 2, cy=h / 2)
    bottom_mortises = tab_and_slot(part="slot", length=W, thickness=T, tabs=2, tab=25 mm, screw=0,
                                   cx=0 mm, cy=ZB + T / 2)
}

# a side, drawn from outside: x along the depth (hand 1: the front at -x), y up
def side(hand=1) -> solid {
    body = Polygon([(-hand * (D / 2 + OVER), 0), (hand * (D / 2 + OVER), 0),
                    (hand * (D / 2 + OVER), HB), (-hand * (D / 2 + OVER), HF)])
    front_mortises = tab_and_slot(part="slot", length=HF, thickness=T, tabs=2, tab=25 mm, screw=0,
                                  rotation=90 deg, cx=-hand * (D / 2 - T / 2), cy=HF / 2)
    back_mortises = tab_and_slot(part="slot", length=HB, thickness=T, tabs=2, tab=25 mm, screw=0,
                                 rotation=90 deg, cx=hand * (D / 2 - T / 2), cy=HB / 2)
    bottom_mortises = tab_and_slot(part="slot", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                                   cx=0 mm, cy=ZB + T / 2)
}

# a pole bracket, drawn from above: y out from the back's outer face
def bracket(bore=26 mm) -> solid {
    plate = Rectangle(bottom_left=(-30, -T), width=60, height=BR_D + T)
    tenon = tab_and_slot(part="tab", length=60, thickness=T, tabs=1, tab=30 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-T)
    hole bore_hole { c = Circle(center=(0, POLE_OFF), diameter=bore) }
}

assembly fruit_picker {
    front = wall(h=HF, tine_h=40 mm)
    back = wall(h=HB, tine_h=55 mm)
    right_side = side(hand=1)
    left_side = side(hand=-1)

    solid bottom {
        board = Rectangle(center=(0, 0), width=W, height=D)
        left_tenons = tab_and_slot(part="tab", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                                   rotation=90 deg, cx=-W / 2, cy=0 mm)
        right_tenons = tab_and_slot(part="tab", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                                    rotation=-90 deg, cx=W / 2, cy=0 mm)
        front_tenons = tab_and_slot(part="tab", length=W, thickness=T, tabs=2, tab=25 mm, screw=0,
                                    rotation=180 deg, cx=0 mm, cy=-D / 2)
        back_tenons = tab_and_slot(part="tab", length=W, thickness=T, tabs=2, tab=25 mm, screw=0,
                                   cx=0 mm, cy=D / 2)
        hole rain { c = Circle(center=(-30, -30), diameter=10) }
        rain_holes = GridPattern(rain, 2, 2, (60, 60))
    }

    lower_bracket = bracket(bore=26 mm)
    solid upper_bracket {
        plate = Rectangle(bottom_left=(-30, -T), width=60, height=BR_D + T)
        tenon = tab_and_slot(part="tab", length=60, thickness=T, tabs=1, tab=30 mm, screw=0,
                             rotation=180 deg, cx=0 mm, cy=-T)
        screw = clearance_hole(size=5, cx=0 mm, cy=POLE_OFF)
        Countersink(screw, diameter=10 mm)
    }

    # the back carries the brackets' mortises; cut them in from here
    hole lower_mortise {
        m = tab_and_slot(part="slot", length=60, thickness=T, tabs=1, tab=30 mm, screw=0,
                         cx=0 mm, cy=20 mm + T / 2)
    }
    hole upper_mortise {
        m = tab_and_slot(part="slot", length=60, thickness=T, tabs=1, tab=30 mm, screw=0,
                         cx=0 mm, cy=120 mm + T / 2)
    }
    AlignCenterX(lower_mortise, back.body)
    lower_mortise.bb.center_y == back.body.bb.bottom + 20 mm + T / 2
    AlignCenterX(upper_mortise, back.body)
    upper_mortise.bb.center_y == back.body.bb.bottom + 120 mm + T / 2
    CutInto(lower_mortise, back)
    CutInto(upper_mortise, back)

    # flat layout
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    RightOf(right_side, back, gap=10)
    AlignBottom(right_side, front)
    RightOf(left_side, right_side, gap=10)
    AlignBottom(left_side, front)
    Above(bottom, front, gap=60)
    AlignLeft(bottom, front)
    RightOf(lower_bracket, left_side, gap=10)
    AlignBottom(lower_bracket, front)
    RightOf(upper_bracket, lower_bracket, gap=10)
    AlignBottom(upper_bracket, front)

    # 3D: x across, y to the back, z up
    Place(front, position=(0, -D / 2 + T, 0), face="front", up="up")
    Place(back, position=(0, D / 2 - T, 0), face="back", up="up")
    Place(right_side, position=(W / 2 - T, 0, 0), face="right", up="up")
    Place(left_side, position=(-W / 2 + T, 0, 0), face="left", up="up")
    Place(bottom, position=(0, 0, ZB), face="up")
    Place(lower_bracket, position=(0, D / 2, 20), face="up")
    Place(upper_bracket, position=(0, D / 2, 120), face="up")

    assert front.body.width == 130 mm and bottom.board.height == 130 mm, "130 x 130 outside"
    assert back.body.height == 150 mm and front.body.height == 80 mm, "walls 150 and 80"
    assert back.tines[0].height == 55 mm and front.tines[0].height == 40 mm, "tines 55 and 40"
    assert len(back.tines) == 5 and len(front.tines) == 5, "five tines"
    assert back.tines[1].center.x - back.tines[0].center.x == 26 mm, "26 mm pitch"
    assert back.tines[0].bottom_width == 14 mm and back.tines[0].top_width == 8 mm, "tines 14 to 8"
    assert right_side.body.bb.width == 130 mm + 2 * 10 mm, "sides 10 mm past front and back"
    assert lower_bracket.bore_hole.c.diameter == 26 mm, "26 mm pole hole"
    assert lower_bracket.bore_hole.c.center.y - lower_bracket.tenon.bb.top == 25 mm, "pole 25 mm off the back"
    assert len(bottom.rain_holes) == 4, "four rain holes"
}
