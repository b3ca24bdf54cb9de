# Request: a tabletop rocking horse for a child's shelf, 6 mm birch ply, glued. Two identical
# side profiles: a rocker 20 mm deep curved on a 300 mm radius (its underside; rounded ends),
# about 205 mm long, carrying a horse: an oval body 110 x 44 mm whose underside is 58 mm above
# the rocker's lowest point, front and back legs 76 mm apart, a neck rising forward to the head,
# a tail, a 4 mm eye hole and a 10 mm hole through the neck for a dowel handle. The sides stand
# 60 mm apart inside, joined by a 60 mm saddle spacer (two 15 mm tabs each side, its top 93 mm
# up) and by a stretcher between the rockers at the middle (one 10 mm tab each side), both
# tabbed through mortises. "DOBBIN" engraved on the outside of the left side, 6 mm letters.
# Corners where the legs meet the body and the rocker rounded r 4.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
gap = 60 mm          # between the sides, inside
rock_r = 300 mm      # the rocker's underside radius
saddle_y = 90 mm     # the saddle spacer's mid-plane above the rocker's lowest point

def horse_side(name="") -> solid {
    path = Arc(center=(0, rock_r), radius=rock_r - 10, start_angle=250 deg, end_angle=290 deg,
               construction=true)
    rocker = Stroke(path, width=20)
    body = Ellipse(center=(0, 80), rx=55, ry=22)
    leg_f = Trapezoid(center=(38, 42), bottom_width=18, top_width=12, height=50)
    leg_b = Trapezoid(center=(-38, 42), bottom_width=18, top_width=12, height=50)
    neck = Slot(start=(38, 88), end=(62, 128), width=22)
    head = Ellipse(center=(75, 130), rx=24, ry=13, rotation=-35 deg)
    ear = Triangle(center=(62, 146), base=8, height=12, rotation=15 deg)
    tail = Slot(start=(-50, 92), end=(-72, 62), width=10)
    hole eye { c = Circle(center=(78, 137), diameter=4) }
    hole handle { c = Circle(center=(50, 108), diameter=10) }
    saddle_slots = tab_and_slot(part="slot", length=gap, thickness=t, tabs=2, tab=15 mm,
                                screw=0, cx=0, cy=saddle_y)
    stretcher_slot = tab_and_slot(part="slot", length=16 mm, thickness=t, tabs=1, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=0, cy=10)
    Fillet([[leg_f, body], [leg_b, body], [leg_f, rocker], [leg_b, rocker]], 4)
    if name != "" {
        drawing label {
            word = Text(name, position=(-5, 70), size=6, valign="middle")
        }
    }
}

assembly rocking_horse {
    left = horse_side(name="DOBBIN")
    right = horse_side()
    solid saddle {
        board = Rectangle(bottom_left=(-30, -t), width=60, height=gap + 2 * t)
        to_left = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=180 deg, cx=0, cy=-t)
        to_right = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm,
                                screw=0, cx=0, cy=gap + t)
    }
    solid stretcher {
        board = Rectangle(bottom_left=(-t, 2), width=gap + 2 * t, height=16)
        to_left = tab_and_slot(part="tab", length=16 mm, thickness=t, tabs=1, tab=10 mm,
                               screw=0, rotation=90 deg, cx=-t, cy=10)
        to_right = tab_and_slot(part="tab", length=16 mm, thickness=t, tabs=1, tab=10 mm,
                                screw=0, rotation=-90 deg, cx=gap + t, cy=10)
    }

    # flat on the sheet
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(saddle, right, gap=10)
    AlignBottom(saddle, left)
    Above(stretcher, saddle, gap=10)
    AlignLeft(stretcher, saddle)

    # in 3D: x forward, z up; the left side's outside face at y = -6, the right side's at gap + 6
    Place(left, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(right, rotation=(90 deg, 0, 0), position=(0, gap + t, 0))
    Place(saddle, position=(0, 0, saddle_y - t / 2))
    Place(stretcher, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))

    assert left.path.radius + left.rocker.bb.height / 2 == 300 mm, "underside on r 300"
    assert left.rocker.bb.height >= 20 mm
    assert left.body.rx * 2 == 110 mm and left.body.ry * 2 == 44 mm
    assert left.body.bb.bottom - left.rocker.bb.bottom == 58 mm
    assert left.leg_f.center.x - left.leg_b.center.x == 76 mm
    assert left.handle.c.diameter == 10 mm and left.eye.c.diameter == 4 mm
    assert saddle.board.width == 60 mm and saddle.board.height - 2 * t == 60 mm
    assert left.saddle_slots.slot[1].bb.top - left.rocker.bb.bottom == 93 mm
    assert len(left.saddle_slots.slot) == 2 and len(left.stretcher_slot.slot) == 1
    assert left.rocker.bb.width >= 200 mm and left.rocker.bb.width <= 215 mm
}
