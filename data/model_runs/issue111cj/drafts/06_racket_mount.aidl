# Request: a wall mount for two tennis rackets hung one in front of the other, 6 mm birch ply.
# A back plate 300 x 120 mm, corners r 8, screwed to the wall by four 4 mm wood screws
# (4.5 mm holes, countersunk for 9 mm heads) 15 mm in from both edges. Two arms 150 mm apart
# (centre to centre) stick out 80 mm from the plate's face; the racket heads rest on them.
# Each arm is 30 mm tall at the plate tapering to 20 mm at its tip, with a lip at the tip
# 8 mm long standing 15 mm above the arm's top; the lip's corners and the inside corner
# rounded r 3, the tip's lower corner r 5. Each arm is glued into the plate by one 20 mm
# tenon through a mortise. "GAME SET MATCH" engraved filled in 10 mm bold letters, centred
# 40 mm below the plate's centre.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
arm_x = 75 mm       # each arm's centre line from the plate's centre

def arm() -> solid {
    # x: out from the plate's face (the tenon runs back to x = -t), y: up
    profile = Polygon([(-t, -15), (80, -5), (80, 30), (72, 30), (72, 15), (-t, 15)])
    tenon = tab_and_slot(part="tab", length=30 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                         rotation=90 deg, cx=-t, cy=0)
    Fillet([(80, 30), (72, 30), (72, 15)], 3)
    Fillet((80, -5), 5)
}

assembly mount {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=300, height=120, corner_radius=8)
        Fixed(body)
        left_mortise = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=20 mm,
                                    screw=0, rotation=90 deg, cx=-arm_x, cy=0)
        right_mortise = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=20 mm,
                                     screw=0, rotation=90 deg, cx=arm_x, cy=0)
        hole screw {
            c = Circle(center=(-135, -45), diameter=4.5)
        }
        screws = CornerPattern(screw, body, inset=15)
        Countersink(screws, diameter=9)
        drawing motto {
            m = Text("GAME SET MATCH", position=(0, -40), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    left_arm = arm()
    right_arm = arm()

    # flat on the sheet
    RightOf(left_arm, plate, gap=10)
    AlignTop(left_arm, plate)
    Below(right_arm, left_arm, gap=10)
    AlignLeft(right_arm, left_arm)

    # in 3D: the wall at y = 6, the plate's face at y = 0, arms out toward -y, z up
    Place(plate, rotation=(90 deg, 0, 0), position=(0, t, 0))
    Place(left_arm, rotation=(90 deg, 0, -90 deg), position=(-arm_x + t / 2, 0, 0))
    Place(right_arm, rotation=(90 deg, 0, -90 deg), position=(arm_x + t / 2, 0, 0))

    assert plate.body.width == 300 mm and plate.body.height == 120 mm
    assert plate.screws[0].c.center.x - plate.body.bb.left == 15 mm
    assert plate.screws[2].c.center.y - plate.body.bb.top == -15 mm
    assert len(plate.screws) == 4
    assert plate.right_mortise.slot[0].bb.center_x - plate.left_mortise.slot[0].bb.center_x
        == 150 mm
    assert left_arm.profile.bb.right - left_arm.tenon.bb.right == 80 mm, "80 mm out"
    assert left_arm.profile.bb.top - 15 mm - 15 mm == left_arm.profile.bb.top - 30 mm
    assert plate.motto.m.position.y - plate.body.center.y == -40 mm
}
