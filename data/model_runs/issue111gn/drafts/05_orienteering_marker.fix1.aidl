# Request (sport): a schoolyard orienteering control marker, 3 mm ply, hung on a cord.
# A triangular prism of three faces, each 150 x 150 mm between the caps, divided on its diagonal:
# the lower-right triangle engraved filled (the orange half), the control code "31" filled in
# the upper-left half, 24 mm sans Bold. Each face has two 30 mm tabs top and bottom (glued,
# 0.15 mm clearance) into slots in two triangular caps. The faces' mid-planes form a triangle
# of 160 mm sides (open corners), the caps stand 5 mm out past the faces (R4 corners). The top
# cap has an 8 mm cord hole in its centre and the code engraved; the bottom cap a 6 mm drain hole.

units mm
thickness 3 mm
import "std/joints.aidl"

code = "31"
face_w = 150 mm
mid_side = 160 mm
r_mid = mid_side / (2 * sqrt(3))      # the mid-planes' triangle's inradius
r_cap = r_mid + 5 mm
normals = [-90 deg, 30 deg, 150 deg]

def panel() -> solid {
    body = Rectangle(center=(0, 0), width=face_w, height=face_w + 6 mm)
    top = tab_and_slot(part="tab", length=face_w, thickness=3 mm, tabs=2, tab=30 mm, screw=0,
                       cx=0 mm, cy=face_w / 2 + 3 mm)
    bottom = tab_and_slot(part="tab", length=face_w, thickness=3 mm, tabs=2, tab=30 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=-face_w / 2 - 3 mm)
    drawing colours {
        orange = Polygon([(-75, -75), (75, -75), (75, 75)], fill=true)
        number = Text(code, position=(-32, 30), size=24, font="sans:Bold", valign="middle", fill=true)
    }
}

def cap(hole_d=8 mm, label=false) -> solid {
    body = RegularPolygon(center=(0, 0), radius=2 * r_cap, sides=3, rotation=90 deg)
    # FIX after the first valid program: Fillet(4) of the whole outline also rounded the slots'
    # ends (note W0410), so the square tabs' corners hit them (W0517): round the outside alone
    Fillet(body, 4)
    for k in range(3) {
        s = tab_and_slot(part="slot", length=face_w, thickness=3 mm, tabs=2, tab=30 mm, screw=0,
                         clearance=0.15 mm, rotation=normals[k] + 90 deg,
                         cx=r_mid * cos(normals[k]), cy=r_mid * sin(normals[k]))
    }
    hole cord { c = Circle(center=(0, 0), diameter=hole_d) }
    if label {
        drawing word { t = Text(code, position=(0, -22), size=10, valign="middle") }
    }
}

assembly control_marker {
    for k in range(3) {
        face = panel()
        # mid-plane on the triangle's side, top face (the colours) outward
        Place(face, position=((r_mid - 1.5 mm) * cos(normals[k]), (r_mid - 1.5 mm) * sin(normals[k]), 78),
              face=(cos(normals[k]), sin(normals[k]), 0), up="up")
    }
    top_cap = cap(hole_d=8 mm, label=true)
    bottom_cap = cap(hole_d=6 mm)
    Place(bottom_cap, position=(0, 0, 0), face="up")
    Place(top_cap, position=(0, 0, 153), face="up")

    RightOf(face[1], face[0], gap=10)
    RightOf(face[2], face[1], gap=10)
    AlignBottom(face[1], face[0])
    AlignBottom(face[2], face[0])
    Below(bottom_cap, face[0], gap=10)
    AlignLeft(bottom_cap, face[0])
    RightOf(top_cap, bottom_cap, gap=10)
    AlignBottom(top_cap, bottom_cap)

    assert len(face) == 3, "three faces"
    assert face[0].top.gap[0].bb.bottom - face[0].bottom.gap[0].bb.top == 150 mm, "150 mm face between the caps"
    assert face[0].body.bb.width == 150 mm, "150 mm wide"
    assert len(face[0].top.gap) == 3, "two tabs a side"
    assert abs(top_cap.s[0].slot[0].bb.width - 30.15 mm) < 0.01 mm, "30 mm tab slot, 0.15 clearance"
    assert top_cap.cord.c.diameter == 8 mm and bottom_cap.cord.c.diameter == 6 mm, "cord and drain holes"
    assert abs(distance(top_cap.s[0].slot[0].bb.center, top_cap.s[0].slot[1].bb.center) - 75 mm) < 0.01 mm, "tabs 75 apart"
}
