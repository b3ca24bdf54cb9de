# Request (sport): a wall hanger for a road bike, hung by its top tube, from 6 mm birch ply,
# glued. Wall plate 220 x 140 mm, corners rounded 10 mm, four countersunk M5 screw holes
# (10 mm heads) 20 mm in from each corner, "RIDE ON" engraved filled (10 mm bold) above the
# arms. Two arms 80 mm apart (centre to centre) stand 170 mm out from the plate's face: 60 mm
# tall at the wall, 25 mm at the tip (the bottom edge slopes), tip corners rounded 5 mm; each
# goes through the plate on two 15 mm tabs. In each arm's top edge a 40 mm round cradle for
# the top tube, centred 115 mm out, 18 mm deep. A 20 mm tall spacer joins the arms 150 mm out,
# its 10 mm tenons through mortises in the arms, flush with their outer faces.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

t = 6 mm
arm_gap = 80 mm      # centre to centre
reach = 170 mm       # from the plate's face
h_wall = 60 mm
h_tip = 25 mm
cradle_x = 115 mm
cradle_d = 40 mm
cradle_depth = 18 mm
spacer_x = 150 mm
spacer_h = 20 mm
spacer_y = 46 mm     # spacer middle, up from the arm's bottom at the wall

def arm() -> solid {
    # local x: out from the wall (0 = the tabs' tips at the plate's back), y: up
    body = Polygon([(0, 0), (t + reach, h_wall - h_tip), (t + reach, h_wall), (0, h_wall)])
    Fillet([body.points[1], body.points[2]], 5)
    root = tab_and_slot(part="tab", length=h_wall, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=h_wall / 2)
    hole cradle { c = Circle(center=(t + cradle_x, h_wall - cradle_depth + cradle_d / 2), diameter=cradle_d) }
    brace = tab_and_slot(part="slot", length=spacer_h, thickness=t, tabs=1, tab=10 mm, screw=0,
                         rotation=90 deg, cx=t + spacer_x, cy=spacer_y)
}

assembly hanger {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=220, height=140, corner_radius=10)
        screw = clearance_hole(size=5)
        screws = CornerPattern(screw, body, inset=20)
        Countersink(screws, diameter=10 mm)
        left_mortise = tab_and_slot(part="slot", length=h_wall, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, rotation=90 deg, cx=-arm_gap / 2, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=h_wall, thickness=t, tabs=2, tab=15 mm,
                                     screw=0, rotation=90 deg, cx=arm_gap / 2, cy=0 mm)
        drawing words {
            t1 = Text("RIDE ON", position=(0, 50), size=10, font="sans:Bold", valign="middle", fill=true)
        }
        Fixed(body)
    }
    left_arm = arm()
    right_arm = arm()
    solid spacer {
        body = Rectangle(center=(0, 0), width=arm_gap + t, height=spacer_h)
        left_tenon = tab_and_slot(part="tab", length=spacer_h, thickness=t, tabs=1, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=-(arm_gap + t) / 2, cy=0 mm)
        right_tenon = tab_and_slot(part="tab", length=spacer_h, thickness=t, tabs=1, tab=10 mm,
                                   screw=0, rotation=-90 deg, cx=(arm_gap + t) / 2, cy=0 mm)
    }

    # on the sheet
    RightOf(left_arm, plate, gap=10)
    AlignTop(left_arm, plate)
    Below(right_arm, left_arm, gap=10)
    AlignLeft(right_arm, left_arm)
    Below(spacer, right_arm, gap=10)
    AlignLeft(spacer, right_arm)

    # on the wall: x across, y out from the wall, z up; the plate's back at y = 0
    Place(plate, rotation=(90 deg, 0, 0), position=(0, t, 0))
    Place(left_arm, rotation=(90 deg, 0, 90 deg), position=(-arm_gap / 2 - t / 2, 0, -h_wall / 2))
    Place(right_arm, rotation=(90 deg, 0, 90 deg), position=(arm_gap / 2 - t / 2, 0, -h_wall / 2))
    Place(spacer, rotation=(90 deg, 0, 0), position=(0, t + spacer_x + t / 2, spacer_y - h_wall / 2))

    # the request's numbers
    assert plate.body.width == 220 mm and plate.body.height == 140 mm, "plate 220 x 140"
    assert len(plate.screws) == 4, "four screws"
    assert plate.screws[0].c.center.x - plate.body.bb.left == 20 mm, "screws 20 mm in"
    assert plate.right_mortise.bb.center_x - plate.left_mortise.bb.center_x == 80 mm, "arms 80 apart"
    assert left_arm.body.bb.width - t == 170 mm, "arms reach 170 mm from the face"
    assert left_arm.body.points[3].y - left_arm.body.points[0].y == 60 mm, "60 tall at the wall"
    assert left_arm.body.points[2].y - left_arm.body.points[1].y == 25 mm, "25 tall at the tip"
    assert left_arm.cradle.c.diameter == 40 mm, "40 mm cradle"
    assert left_arm.cradle.c.center.x - left_arm.body.points[0].x - t == 115 mm, "cradle 115 out"
    assert left_arm.body.points[3].y - left_arm.cradle.c.bb.bottom == 18 mm, "cradle 18 deep"
    assert spacer.body.bb.width + 2 * t == arm_gap + 3 * t, "spacer's tenons flush with the arms' outer faces"
}
