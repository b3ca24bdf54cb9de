# Request: a fold-flat camping solar panel cooker, 3 mm ply (foil glued on the inside).
# The reflector is one piece 560 x 300 mm: a back panel 240 mm wide, two living-hinge
# bands 20 mm wide (pitch 2, cuts 15, bridges 3) and two wings 140 mm wide whose top outer
# corners are cut off 40 mm at 45 deg; a 5 mm cord hole in each wing 15 mm in from its outer
# edge and 30 mm below the top, and two in the back panel 15 mm in from its sides and 10 mm
# below the top, for cords that hold the wings forward at 45 deg. The back panel stands
# on a 240 x 240 mm floor by two 40 mm tabs through mortises (0.15 mm clearance) whose
# middle is 10 mm in from the floor's back edge; the wings reach down to the ground beside
# the floor. The floor has the pot's place engraved (a 180 mm circle, 10 mm behind the
# floor's middle) and "SOLAR COOKER" (10 mm bold sans, filled) 105 mm in front of the middle.

units mm
thickness 3 mm
import "std/joints.aidl"
import "std/plates.aidl"

BAND = 20 mm
Rm = BAND / (pi / 4)      # the band bent 45 deg: its mid-thickness radius
s45 = sin(45 deg)

assembly cooker {
    solid reflector {
        body = Rectangle(center=(0, 0), width=560, height=300)
        Chamfer([body.top_left, body.top_right], 40)
        left_hinge = living_hinge(width=BAND, height=300, pitch=2, cut=15, bridge=3, cx=-130, cy=0)
        right_hinge = living_hinge(width=BAND, height=300, pitch=2, cut=15, bridge=3, cx=130, cy=0)
        feet = tab_and_slot(part="tab", length=240, thickness=3, tabs=2, tab=40, screw=0,
                            rotation=180 deg, cx=0, cy=-150)
        hole cords {
            wl = Circle(center=(-265, 120), diameter=5)
            wr = Circle(center=(265, 120), diameter=5)
            bl = Circle(center=(-105, 140), diameter=5)
            br = Circle(center=(105, 140), diameter=5)
        }
    }

    solid floor {
        body = Rectangle(center=(0, 0), width=240, height=240)
        mort = tab_and_slot(part="slot", length=240, thickness=3, tabs=2, tab=40, screw=0,
                            clearance=0.15, cx=0, cy=110)
        drawing marks {
            pot = Circle(center=(0, 10), diameter=180)
            name = Text("SOLAR COOKER", position=(0, -105), size=10, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }

    Below(floor, reflector, gap=10)
    AlignCenterX(floor, reflector)

    # assembled: the floor flat; the reflector standing on it, its top (foil) face to the
    # front, the left wing placed at 45 deg so that after the two bends the back panel
    # faces the front squarely and both wings come forward 45 deg
    Place(floor, position=(0, -111.5, 0), rotation=(0, 0, 0))
    Place(reflector,
          position=(-120 - Rm * s45 + 140 * s45 - 1.5 * s45,
                    -1.5 - Rm * (1 - s45) + 140 * s45 + 1.5 * s45, 150),
          rotation=(90 deg, 0, 45 deg))
    Bend(reflector, at=-130, angle=45 deg, radius=Rm - 1.5 mm)
    Bend(reflector, at=130, angle=45 deg, radius=Rm - 1.5 mm)

    # the request's numbers
    assert reflector.body.width == 560 mm and reflector.body.height == 300 mm, "reflector 560 x 300"
    assert reflector.left_hinge.width == 20 mm and reflector.right_hinge.cx - reflector.left_hinge.cx == 260 mm, "bands 20 wide either side of a 240 panel"
    assert reflector.body.bb.right - reflector.right_hinge.cx - BAND / 2 == 140 mm, "wings 140 wide"
    assert reflector.cords.wr.center.x == reflector.body.bb.right - 15 mm, "wing cord hole 15 in"
    assert reflector.body.bb.top - reflector.cords.wr.center.y == 30 mm, "wing cord hole 30 down"
    assert reflector.cords.br.center.x == reflector.right_hinge.cx - BAND / 2 - 15 mm, "back cord hole 15 in"
    assert reflector.body.bb.top - reflector.cords.br.center.y == 10 mm, "back cord hole 10 down"
    assert len(floor.mort.slot) == 2 and floor.mort.slot[0].bb.width == 40.15 mm, "two 40 mm tabs"
    assert floor.body.bb.top - floor.mort.slot[0].bb.center_y == 10 mm, "mortises 10 in from the back"
    assert floor.marks.pot.diameter == 180 mm, "180 mm pot circle"
    assert floor.marks.pot.center.y - floor.body.center.y == 10 mm, "pot circle 10 behind the middle"
    assert floor.body.center.y - floor.marks.name.position.y == 105 mm, "name 105 in front"
    assert distance(floor.marks.name, floor.marks.pot) >= 5 mm, "name clear of the pot circle"
}
