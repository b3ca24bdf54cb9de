# Request (parties): "A beer pong rack that holds the ten standard 16 oz party cups (95 mm
# rims) in their triangle, 4 mm birch ply. A triangular top plate 60 mm above the table with
# ten 82 mm holes on a 96 mm pitch (rows of 4, 3, 2, 1), its outline 65 mm round each corner
# cup's centre (rounded corners, straight edges). Three 120 x 60 mm legs, one under the
# middle of each edge and parallel to it, each with a 30 mm tenon glued into a mortise
# (0.15 mm play) centred 53 mm out from the line through the edge cups' centres, an arch
# 67 mm wide and 15 mm high cut out of its foot, and 'PONG' engraved filled, bold, 10 mm."

import "std/joints.aidl"

thickness 4 mm

pitch = 96 mm
row_h = pitch * sqrt(3) / 2
margin = 65 mm
mort = 53 mm
# the edges: midpoint of the line through the edge cups' centres, its outward normal angle
mids = [(0 mm, 0 mm), (pitch * 3 / 4, row_h * 1.5), (-pitch * 3 / 4, row_h * 1.5)]
normals = [270 deg, 30 deg, 150 deg]

def pong_leg() -> solid {
    body = Rectangle(bottom_left=(-60, 0), width=120, height=64)
    tenon = tab_and_slot(part="tab", length=120 mm, thickness=4 mm, tabs=1, tab=30 mm,
                         screw=0, cx=0 mm, cy=64 mm)
    hole arch { c = Circle(center=(0, -30), radius=45) }
    drawing word {
        t = Text("PONG", position=(0, 36), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

assembly pong_rack {
    solid plate {
        outline = Hull(Circle(center=(-1.5 * pitch, 0), radius=margin),
                       Circle(center=(1.5 * pitch, 0), radius=margin),
                       Circle(center=(0, 3 * row_h), radius=margin))
        hole cups {
            for r in range(4) {
                for c in range(4 - r) {
                    h = Circle(center=((c - (3 - r) / 2) * pitch, r * row_h), diameter=82)
                }
            }
        }
        for k in range(3) {
            m = tab_and_slot(part="slot", length=120 mm, thickness=4 mm, tabs=1, tab=30 mm,
                             screw=0, clearance=0.15 mm, rotation=normals[k] + 90 deg,
                             cx=mids[k][0] + mort * cos(normals[k]),
                             cy=mids[k][1] + mort * sin(normals[k]))
        }
    }

    for k in range(3) {
        leg = pong_leg()
        # stood up on its edge, its inner face against the mortise's inner side
        Place(leg, position=(mids[k][0] + (mort - 2 mm) * cos(normals[k]),
                             mids[k][1] + (mort - 2 mm) * sin(normals[k]), 0),
              rotation=(90 deg, 0, normals[k] - 270 deg))
    }
    Place(plate, position=(0, 0, 60))

    # laid out flat: the legs in a row under the plate
    Below(leg[0], plate, gap=8)
    AlignLeft(leg[0], plate)
    RightOf(leg[1], leg[0], gap=8)
    RightOf(leg[2], leg[1], gap=8)
    AlignTop(leg[1], leg[0])
    AlignTop(leg[2], leg[0])

    # the request's numbers
    assert sum([len(plate.cups.h[r]) for r in range(4)]) == 10, "ten cups"
    assert len(plate.cups.h[0]) == 4 and len(plate.cups.h[3]) == 1, "rows of 4 to 1"
    assert plate.cups.h[1][0].diameter == 82 mm, "82 mm holes"
    assert abs(distance(plate.cups.h[0][0].center, plate.cups.h[0][1].center) - 96 mm) < 0.001 mm, "96 pitch"
    assert abs(distance(plate.cups.h[0][0].center, plate.cups.h[1][0].center) - 96 mm) < 0.001 mm, "96 pitch across rows"
    assert abs(plate.cups.h[0][0].center.y - plate.outline.bb.bottom - 65 mm) < 0.001 mm, "65 mm round the corner cups"
    assert leg[0].body.width == 120 mm and leg[0].body.height - 4 mm == 60 mm, "legs 120 x 60"
    assert len(plate.m) == 3 and len(leg) == 3, "three legs"
    assert abs(plate.m[0].slot[0].bb.center_y - plate.cups.h[0][0].center.y + 53 mm) < 0.001 mm, "mortise 53 out"
    assert leg[1].arch.c.center.y + leg[1].arch.c.radius - leg[1].body.bb.bottom == 15 mm, "arch 15 high"
    assert abs(2 * sqrt(45 mm ** 2 - 30 mm ** 2) - 67 mm) < 0.5 mm, "arch 67 wide"
}
