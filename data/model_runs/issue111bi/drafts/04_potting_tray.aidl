# Request: a potting tray for repotting on the garden table, open at the front so I can sweep
# the soil back into the bag. 6 mm exterior ply, finger-jointed (40 mm fingers) and glued.
# - base 500 x 350 mm (outside sizes);
# - back wall 500 wide x 200 tall, with "POTTING" engraved filled (40 mm letters) on its
#   inside face and a 12 mm hole 20 mm below its top edge, centred, to hang it in the shed;
# - two side walls 350 deep, 200 tall at the back sloping straight down to 60 tall at the
#   front, the front top corner rounded r15, each with a 100 x 30 mm handhold slot parallel to
#   the sloping top edge, 20 mm below it, its centre 85 mm in front of the back.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
W = 500 mm       # across
DEEP = 350 mm    # front to back
BACK_H = 200 mm
FRONT_H = 60 mm
F = 40 mm        # finger width

SLOPE = (BACK_H - FRONT_H) / DEEP
HX = DEEP - 85 mm   # the handhold's centre, from the front

# a side wall seen from outside the left: x = distance from the front, y = height
def side() -> solid {
    body = Polygon([(0, 0), (DEEP, 0), (DEEP, BACK_H), (0, FRONT_H)])
    bottom = finger_edge(length=DEEP, thickness=T, finger=F, start="gap", rotation=180 deg,
                         cx=DEEP / 2, cy=0)
    back = finger_edge(length=BACK_H, thickness=T, finger=F, start="gap", rotation=-90 deg,
                       cx=DEEP, cy=BACK_H / 2)
    hole handhold {
        s = Slot(center=(HX, FRONT_H + SLOPE * HX - (20 mm + 15 mm) / cos(atan(SLOPE))),
                 length=100, width=30, rotation=atan(SLOPE))
    }
    Fillet(body.points[3], 15)
}

assembly potting_tray {
    # plan view: x across, y from the front (0) to the back
    solid base {
        body = Rectangle(center=(0, DEEP / 2), width=W, height=DEEP)
        back = finger_edge(length=W, thickness=T, finger=F, start="tab", rotation=0 deg,
                           cx=0, cy=DEEP)
        left = finger_edge(length=DEEP, thickness=T, finger=F, start="tab", rotation=90 deg,
                           cx=-W / 2, cy=DEEP / 2)
        right = finger_edge(length=DEEP, thickness=T, finger=F, start="tab", rotation=-90 deg,
                            cx=W / 2, cy=DEEP / 2)
    }

    # seen from the front (its inside face): x across, y = height
    solid back_wall {
        body = Rectangle(center=(0, BACK_H / 2), width=W, height=BACK_H)
        bottom = finger_edge(length=W, thickness=T, finger=F, start="gap", rotation=180 deg,
                             cx=0, cy=0)
        left = finger_edge(length=BACK_H, thickness=T, finger=F, start="tab", rotation=90 deg,
                           cx=-W / 2, cy=BACK_H / 2)
        right = finger_edge(length=BACK_H, thickness=T, finger=F, start="tab", rotation=-90 deg,
                            cx=W / 2, cy=BACK_H / 2)
        hole hang {
            c = Circle(center=(0, BACK_H - 20), diameter=12)
        }
        drawing name {
            t = Text("POTTING", position=(0, 95), size=40, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    left_side = side()
    right_side = side()

    # on the sheet
    Above(back_wall, base, gap=10)
    AlignCenterX(back_wall, base)
    RightOf(left_side, base, gap=10)
    AlignBottom(left_side, base)
    Above(right_side, left_side, gap=10)
    AlignLeft(right_side, left_side)

    # in 3D: x across, y from the front, z up
    Place(base, position=(0, 0, 0))
    Place(back_wall, position=(0, DEEP, 0), rotation=(90 deg, 0, 0))
    Place(left_side, position=(-W / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_side, position=(W / 2 - T, 0, 0), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert base.body.bb.width == 500 mm and base.body.bb.height == 350 mm, "base 500 x 350"
    assert back_wall.body.bb.width == 500 mm and back_wall.body.bb.height == 200 mm, "back 500 x 200"
    assert left_side.body.points[2].y - left_side.body.points[1].y == 200 mm, "200 at the back"
    assert left_side.body.points[3].y - left_side.body.points[0].y == 60 mm, "60 at the front"
    assert left_side.body.points[1].x - left_side.body.points[0].x == 350 mm, "350 deep"
    assert left_side.handhold.s.length == 100 mm and left_side.handhold.s.width == 30 mm, "handhold"
    assert left_side.body.points[2].x - left_side.handhold.s.center.x == 85 mm, "85 from the back"
    assert back_wall.body.bb.top - back_wall.hang.c.center.y == 20 mm, "hang hole 20 below the top"
    assert back_wall.hang.c.diameter == 12 mm, "12 mm hang hole"
    assert back_wall.name.t.size == 40 mm, "40 mm letters"
}
