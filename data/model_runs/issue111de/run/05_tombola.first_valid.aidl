# Request: a tombola (raffle-ticket drum) for the school summer fair, all 4 mm ply.
# - Drum: two hexagonal end plates 200 mm across the corners, 240 mm apart inside, joined by six
#   slats 88 mm wide whose two 20 mm tabs at each end go through mortises in the end plates
#   (slat mid-planes 78.6 mm from the axle, i.e. 8 mm in from each flat); M8 axle holes.
# - One slat (the top one at rest) has a 140 x 50 mm ticket opening, closed by a door 160 x 64 mm
#   on two small hinges (M3 holes, two per leaf, 16 mm apart, 50 mm either side of the middle,
#   7 mm from the hinge line on each leaf) with a 15 mm finger hole 20 mm above the door's middle.
# - The front upper slat has "TOMBOLA" engraved filled, bold sans, 30 mm high, centred.
# - Stand: two uprights (a trapezoid 220 mm wide at the foot, 50 mm at 130 mm up, topped by a
#   25 mm radius round head), the axle 130 mm above the table, 10 mm outside the end plates;
#   two stretchers 30 mm tall, 10-40 mm up, 80 mm in front of and behind the axle, tenoned
#   (one 20 mm tenon) through the uprights.
# - A crank arm 80 mm between centres, 24 mm wide, M8 hole and a 10 mm hole for a dowel handle,
#   10 mm outside the right upright.
# The drum must clear the table and the stretchers by at least 20 mm.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 4 mm

t = 4 mm
R = 100 mm              # end plate, centre to corner
a_s = 78.6 mm           # slat mid-plane from the axle
slat_w = 88 mm
inner = 240 mm          # between the end plates
axle_z = 130 mm
gap_nut = 10 mm
up_x = inner / 2 + t + gap_nut      # the uprights' inner faces
st_y = 80 mm

def end_plate() -> solid {
    body = RegularPolygon(center=(0, 0), radius=R, sides=6)
    axle = clearance_hole(size=8)
    for k in range(6) {
        m = tab_and_slot(part="slot", length=slat_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                         rotation=30 deg + k * 60 deg + 90 deg,
                         cx=a_s * cos(30 deg + k * 60 deg), cy=a_s * sin(30 deg + k * 60 deg))
    }
    Fixed(body)
}

# a slat: x along the drum (tab tips at both ends), y across
def slat(door=false, label=false) -> solid {
    body = Rectangle(center=(0, 0), width=inner + 2 * t, height=slat_w)
    right_end = tab_and_slot(part="tab", length=slat_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=-90 deg, cx=inner / 2 + t, cy=0 mm)
    left_end = tab_and_slot(part="tab", length=slat_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=90 deg, cx=-(inner / 2 + t), cy=0 mm)
    Fixed(body)
    if door {
        hole opening { r = Rectangle(center=(0, 0), width=140, height=50) }
        # the hinges' slat leaves: 7 mm below the hinge line (the door's bottom edge, y = -32)
        for x in [-58, -42, 42, 58] {
            h = clearance_hole(size=3, cx=x * 1 mm, cy=-39 mm)
        }
    }
    if label {
        drawing word {
            w = Text("TOMBOLA", position=(0, 0), size=30 mm, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

assembly tombola {
    end_right = end_plate()
    end_left = end_plate()
    door_slat = slat(door=true)
    label_slat = slat(label=true)
    for k in range(4) {
        plain = slat()
    }

    solid door {
        body = RoundedRectangle(center=(0, 0), width=160, height=64, corner_radius=4)
        hole finger { c = Circle(center=(0, 20), diameter=15) }
        # the hinges' door leaves: 7 mm above the hinge line (its bottom edge)
        for x in [-58, -42, 42, 58] {
            h = clearance_hole(size=3, cx=x * 1 mm, cy=-25 mm)
        }
        Fixed(body)
    }

    def upright() -> solid {
        leg = Trapezoid(center=(0, axle_z / 2), bottom_width=220, top_width=50, height=axle_z)
        head = Circle(center=(0, axle_z), radius=25)
        axle = clearance_hole(size=8, cx=0 mm, cy=axle_z)
        front_m = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                               rotation=90 deg, cx=-st_y, cy=25 mm)
        back_m = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                              rotation=90 deg, cx=st_y, cy=25 mm)
        Fixed(leg)
        Fixed(head)
    }
    up_right = upright()
    up_left = upright()

    def stretcher() -> solid {
        body = Rectangle(center=(0, 0), width=2 * up_x + 2 * t, height=30)
        r_end = tab_and_slot(part="tab", length=30 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                             rotation=-90 deg, cx=up_x + t, cy=0 mm)
        l_end = tab_and_slot(part="tab", length=30 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                             rotation=90 deg, cx=-(up_x + t), cy=0 mm)
        Fixed(body)
    }
    st_front = stretcher()
    st_back = stretcher()

    solid crank {
        arm = Slot(start=(0, 0), end=(0, -80), width=24)
        axle = clearance_hole(size=8, cx=0 mm, cy=0 mm)
        hole handle { c = Circle(center=(0, -80), diameter=10) }
        Fixed(arm)
    }

    # ---- on the sheet
    RightOf(end_left, end_right, gap=6)
    AlignTop(end_left, end_right)
    RightOf(up_right, end_left, gap=6)
    AlignTop(up_right, end_left)
    RightOf(up_left, up_right, gap=6)
    AlignTop(up_left, up_right)
    Below(door_slat, end_right, gap=6)
    AlignLeft(door_slat, end_right)
    Below(label_slat, door_slat, gap=6)
    AlignLeft(label_slat, door_slat)
    for k in range(4) {
        plain[k].bb.top == label_slat.bb.bottom - 6 mm - k * (slat_w + 6 mm)
        AlignLeft(plain[k], label_slat)
    }
    RightOf(door, door_slat, gap=6)
    AlignTop(door, door_slat)
    Below(st_front, up_right, gap=6)
    AlignLeft(st_front, up_right)
    Below(st_back, st_front, gap=6)
    AlignLeft(st_back, st_front)
    RightOf(crank, door, gap=6)
    AlignTop(crank, door)

    # ---- in 3D: the axle along x, 130 mm above the table (z = 0), y = 0
    Place(end_right, position=(inner / 2, 0, axle_z), face="right", up="up")
    Place(end_left, position=(-inner / 2, 0, axle_z), face="left", up="up")
    # a slat on the face whose outward normal is at angle p in the right end plate's drawing
    # (drawing x -> y, drawing y -> z): its top face outward, turned about x by p - 90 deg
    Place(door_slat, rotation=(0 deg, 0, 0), position=(0, 0, axle_z + a_s - t / 2))
    Place(door, rotation=(0 deg, 0, 0), position=(0, 0, axle_z + a_s + t / 2))
    Place(label_slat, rotation=(150 deg - 90 deg, 0, 0),
          position=(0, (a_s - t / 2) * cos(150 deg), axle_z + (a_s - t / 2) * sin(150 deg)))
    for k in range(4) {
        Place(plain[k], rotation=([30, 210, 270, 330][k] * 1 deg - 90 deg, 0, 0),
              position=(0, (a_s - t / 2) * cos([30, 210, 270, 330][k] * 1 deg),
                        axle_z + (a_s - t / 2) * sin([30, 210, 270, 330][k] * 1 deg)))
    }
    Place(up_right, position=(up_x, 0, 0), face="right", up="up")
    Place(up_left, position=(-up_x, 0, 0), face="left", up="up")
    Place(st_front, position=(0, -(st_y - t / 2), 25), face="front", up="up")
    Place(st_back, position=(0, st_y - t / 2, 25), face="back", up="up")
    Place(crank, position=(up_x + t + gap_nut, 0, axle_z), face="right", up="up")

    # ---- the request's numbers
    assert end_right.body.radius * 2 == 200 mm, "200 across the corners"
    assert door_slat.body.bb.width - 2 * t == 240 mm, "240 between the end plates"
    assert door_slat.opening.r.bb.width == 140 mm and door_slat.opening.r.bb.height == 50 mm, "opening 140 x 50"
    assert door.body.bb.width == 160 mm and door.body.bb.height == 64 mm, "door 160 x 64"
    assert door.h[3].c.center.x - door.h[2].c.center.x == 16 mm, "hinge holes 16 apart"
    assert door.h[0].c.center.y - door.body.bb.bottom == 7 mm, "7 mm above the hinge line"
    assert (door.body.bb.bottom + 0 mm) - door_slat.h[0].c.center.y == 7 mm, "7 mm below the hinge line"
    assert door.finger.c.center.y - door.body.center.y == 20 mm, "finger hole 20 above the middle"
    assert 86.6 mm - (a_s + t / 2) >= 5 mm, "mortises 8 mm in from each flat"
    assert up_right.axle.c.center.y == 130 mm, "axle 130 up"
    assert up_right.leg.bb.width == 220 mm, "220 at the foot"
    assert crank.handle.c.center.y - crank.axle.c.center.y == -80 mm, "crank 80"
    # clearances of the turning drum (its corners reach R)
    assert axle_z - R >= 20 mm, "drum clears the table"
    assert (axle_z - sqrt(R ** 2 - (st_y - t / 2) ** 2)) - 40 mm >= 20 mm, "drum clears the stretchers"
    assert up_x - (inner / 2 + t) == 10 mm, "uprights 10 outside the end plates"
}
