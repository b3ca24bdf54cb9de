# Request: a pool-depth sign for the wall by our pool steps, three layers of 3 mm acrylic
# glued up. A white backer and a blue face, both 300 x 150 mm with R10 corners, screwed to
# the wall with four M4 countersunk screws 12 mm in from each corner (9 mm heads sunk in the
# face). Cut through the blue face so the white shows: "1.2 m" (bold sans, 40 mm) and "4 FT"
# (bold sans, 24 mm) on the right, stencilled so no counter falls out; on the left a diver
# figure (head, body, arms reaching forward) and "NO DIVING" (9 mm) under it. On top of the
# face, a red prohibition sign cut from the third sheet: a ring 90 mm outside, 74 inside,
# centred 90 mm left of the middle, with an 8 mm slash from top left to bottom right.

import "std/fasteners.aidl"

t = 3 mm
thickness t

def sign_plate(face=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=300, height=150, corner_radius=10)
    screw = clearance_hole(size=4)
    corners = CornerPattern(screw, body, inset=12 mm)
    if face {
        Countersink(corners, diameter=9 mm)
        hole depth {
            metres = Text("1.2 m", position=(55, 15), size=40, font="sans:Bold", stencil=true,
                          valign="middle")
            feet = Text("4 FT", position=(55, -40), size=24, font="sans:Bold", stencil=true,
                        valign="middle")
        }
        # FIX after the first valid program: the figure went up and to the right, a
        # jumper rather than a diver; now it dives head first over a short wave line.
        # FIX 2: diving down to the right it lay right under the red slash (top left to
        # bottom right); it dives down to the LEFT, across the slash
        hole diver {
            head = Circle(center=(-98, -20), radius=5)
            trunk = Stroke(Polyline([(-70, 18), (-88, 2), (-102, -10)]), width=7)
            arms = Stroke(Line((-102, -10), (-116, -20)), width=4)
            water = Stroke(Polyline([(-100, -33), (-95, -30), (-90, -33), (-85, -30), (-80, -33)]),
                           width=3)
        }
        hole warning {
            words = Text("NO DIVING", position=(-90, -58), size=9, font="sans:Bold",
                         stencil=true, valign="middle")
        }
    }
}

def prohibition() -> solid {
    ring = Shell(Circle(center=(-90, 0), diameter=74), 8)
    slash = Rectangle(center=(-90, 0), width=76, height=8, rotation=-45 deg)
}

assembly pool_sign {
    face = sign_plate(face=true)
    backer = sign_plate(face=false)
    no_dive = prohibition()

    Below(backer, face, gap=8)
    AlignLeft(backer, face)
    RightOf(no_dive, face, gap=8)
    AlignTop(no_dive, face)

    Place(backer, position=(0, 0, 0))
    Place(face, position=(0, 0, t))
    Place(no_dive, position=(0, 0, 2 * t))

    # the request's numbers
    assert abs(face.body.width - 300 mm) < 0.01 mm and abs(face.body.height - 150 mm) < 0.01 mm, "300 x 150"
    assert len(face.corners) == 4, "four screws"
    assert abs(face.corners[0].c.center.x - face.body.bb.left - 12 mm) < 0.01 mm and abs(face.corners[0].c.center.y - face.body.bb.bottom - 12 mm) < 0.01 mm, "screws 12 mm in"
    assert abs(no_dive.ring.bb.width - 90 mm) < 0.01 mm, "ring 90 mm outside"
    assert abs(no_dive.ring.bb.center_x - face.body.bb.center_x + 90 mm) < 0.01 mm, "ring 90 mm left of the middle"
    assert distance(face.depth, face.corners) >= 5 mm and distance(face.warning, face.corners) >= 5 mm, "lettering clear of the screws"
    assert face.diver.bb.left >= face.body.bb.center_x - 90 mm - 37 mm and face.diver.bb.right <= face.body.bb.center_x - 90 mm + 37 mm and
           face.diver.bb.top <= face.body.bb.center_y + 37 mm and face.diver.bb.bottom >= face.body.bb.center_y - 37 mm, "the diver inside the ring's 74 mm"
    assert face.depth.bb.left >= no_dive.ring.bb.right + 10 mm, "the depth clear of the sign"
    assert face.warning.bb.top <= no_dive.ring.bb.bottom - 3 mm, "NO DIVING under the ring"
    assert face.depth.bb.right <= face.body.bb.right - 20 mm, "the depth inside the face"
}
