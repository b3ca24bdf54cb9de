# Request: a "Santa cam" for Christmas: a fake security camera on a wall bracket that tells
# the children Santa is watching. 3 mm ply.
# - Camera body: a closed finger-jointed box 55 wide x 110 long x 55 tall outside (10 mm
#   fingers), its long axis pointing out from the wall. On its front end a 30 mm lens hole in
#   the middle and a 5 mm hole for a red LED 19 mm right of and 19 mm above the lens centre;
#   a lens ring (44 mm outside, 30 mm inside) glued round the lens. "SANTA CAM" engraved
#   filled (sans Bold, 10 mm) along the right side, reading the right way up.
# - Bracket: a wall plate 70 x 90 mm (R6) with two 4.5 mm screw holes countersunk for 9 mm
#   heads, 15 mm in from its top and bottom ends; an arm standing on edge, its 20 mm tenon in a
#   3.2 x 20.2 mortise of the wall plate, its top edge under the camera's bottom with a 30 mm
#   tenon in a 3.2 x 30.2 mortise of the bottom panel. The camera's back end stands 30 mm off
#   the wall; the arm is 50 mm deep at the wall, tapering to 12 mm at its front end,
#   25 mm behind the camera's front.

thickness 3 mm
import "std/joints.aidl"

assembly santa_cam {
    cam = finger_box(length=55 mm, depth=110 mm, height=55 mm, thickness=3 mm, finger=10 mm)

    hole lens { c = Circle(center=(0, 0), diameter=30) }
    CenterInside(lens, cam.front)
    CutInto(lens, cam.front)

    hole led { c = Circle(center=(0, 0), diameter=5) }
    led.c.center.x == cam.front.bb.center_x + 19
    led.c.center.y == cam.front.bb.center_y + 19
    CutInto(led, cam.front)

    drawing words {
        t = Text("SANTA CAM", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 rotation=-90 deg, fill=true)
    }
    CenterInside(words, cam.right)
    CutInto(words, cam.right)

    # the arm's top tenon: world y -20 .. 10 under the camera (its bottom spans -55 .. 55)
    hole arm_mortise { m = Rectangle(center=(0, 0), width=3.2, height=30.2) }
    AlignCenterX(arm_mortise, cam.bottom)
    arm_mortise.m.center.y == cam.bottom.bb.center_y - 5
    CutInto(arm_mortise, cam.bottom)

    solid lens_ring {
        c = Circle(center=(0, 0), diameter=44)
        hole bore { b = Circle(center=(0, 0), diameter=30) }
    }

    solid wall {
        plate = RoundedRectangle(center=(0, 0), width=70, height=90, corner_radius=6)
        hole screw_top { c = Circle(center=(0, 30), diameter=4.5) }
        hole screw_bottom { c = Circle(center=(0, -30), diameter=4.5) }
        hole mortise { m = Rectangle(center=(0, -5), width=3.2, height=20.2) }
        Countersink([screw_top, screw_bottom], diameter=9)
        Fixed(plate)
    }

    solid arm {
        # local x = the world's y (front to back), local y = the world's z (camera bottom at 0)
        web = Polygon([(-30, 0), (85, 0), (85, -50), (-30, -12)])
        back_tenon = Rectangle(bottom_left=(85, -35), width=3, height=20)
        top_tenon = Rectangle(bottom_left=(-20, 0), width=30, height=3)
    }

    # flat on the sheet
    RightOf(wall, cam, gap=10)
    AlignTop(wall, cam)
    Below(arm, wall, gap=10)
    AlignLeft(arm, wall)
    Below(lens_ring, arm, gap=10)
    AlignLeft(lens_ring, arm)

    # in 3D: the box stands on z = 0 centred on x = y = 0 (its own Place); the wall's front face
    # at y = 85 (the box's back at 55, 30 off the wall)
    Place(wall, position=(0, 88, -20), face="front", up="up")
    Place(arm, position=(-1.5, 0, 0), face="right", up="up")
    Place(lens_ring, position=(0, -55, 27.5), face="front", up="up")

    assert cam.length == 55 mm and cam.depth == 110 mm and cam.height == 55 mm, "box size"
    assert lens.c.diameter == 30 mm and led.c.diameter == 5 mm, "lens and LED"
    assert lens_ring.c.diameter == 44 mm and lens_ring.bore.b.diameter == 30 mm, "ring"
    # the LED stays clear of the ring glued round the lens
    assert distance(led.c.center, lens.c.center) - 2.5 mm >= 22 mm + 1 mm, "LED beside the ring"
    assert wall.plate.bb.width == 70 mm and wall.plate.bb.height == 90 mm, "wall plate"
    assert wall.plate.bb.top - wall.screw_top.c.center.y == 15 mm, "screw 15 in"
    assert wall.screw_bottom.c.center.y - wall.plate.bb.bottom == 15 mm, "screw 15 in"
    assert arm.web.bb.height == 50 mm, "arm 50 deep at the wall"
    # the arm's front end is 25 behind the camera's front (y = -55)
    assert arm.web.bb.left - (-55 mm) == 25 mm, "arm front"
    assert 85 mm - 55 mm == 30 mm, "30 off the wall"
}
