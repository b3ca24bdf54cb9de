# Request (signs): a projecting "hearing loop" sign for a reception corridor, 3 mm white
# acrylic, engraved in filled areas so the symbol reads on both sides. Two faces 160 x 200 mm
# (R8 on the free corners) glued back to back stand out from the wall; each has two 40 mm
# tenons on its wall edge, which pass together through a 6 mm mortise in a wall bracket
# 60 x 200 (R6) fixed by four countersunk M4 screws (8.4 mm heads) 18 mm either side of the
# mortise and 75 mm above and below the middle. Each face: a 2 mm border 4 mm inside its
# visible edge; the UK loop symbol: an ear (a 6 mm stroke, about 50 x 85), its inner curl
# (5 mm), a 6 mm diagonal bar across it and a bold "T" 26 mm tall at its lower right; under it
# "HEARING LOOP" bold 14 mm (at most 135 wide), "Switch your hearing aid to T" 6 mm and
# "Ask at reception for help" 5 mm, all centred on the visible face.

units mm
thickness 3 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

T = 3 mm
W = 160 mm
H = 200 mm
ear_y = 38 mm
ear_pts = [(-22, 10), (-18, 30), (0, 42), (20, 35), (27, 15), (20, -5), (8, -15), (4, -30),
           (-6, -42), (-16, -38)]
curl_pts = [(-8, 5), (-8, 20), (4, 24), (10, 12), (3, 3)]

def sign_face(side=-1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H,
                            corner_radii=([0, 8, 8, 0] if side < 0 else [8, 0, 0, 8]))
    tenons = tab_and_slot(part="tab", length=H, thickness=T, tabs=2, tab=40 mm, screw=0,
                          rotation=(90 deg if side < 0 else -90 deg), cx=side * W / 2, cy=0 mm)
    drawing art {
        border = Shell(RoundedRectangle(center=(-side * T / 2, 0), width=W - T - 12 mm,
                                        height=H - 12 mm, corner_radius=5), 2, fill=true)
        ear = Stroke(Spline([(-side * T / 2 + p[0] * 1 mm, ear_y + p[1] * 1 mm) for p in ear_pts]),
                     6, fill=true)
        curl = Stroke(Spline([(-side * T / 2 + p[0] * 1 mm, ear_y + p[1] * 1 mm) for p in curl_pts]),
                      5, fill=true)
        bar = Stroke(Line((-side * T / 2 - 40 mm, ear_y - 42 mm), (-side * T / 2 + 40 mm, ear_y + 42 mm)),
                     6, fill=true)
        tee = Text("T", position=(-side * T / 2 + 40 mm, 2), size=26, font="sans:Bold", fill=true)
        name = Text("HEARING LOOP", position=(-side * T / 2, -30), size=14, font="sans:Bold",
                    valign="middle", max_width=135 mm, fill=true)
        line1 = Text("Switch your hearing aid to T", position=(-side * T / 2, -55), size=6,
                     valign="middle")
        line2 = Text("Ask at reception for help", position=(-side * T / 2, -70), size=5,
                     valign="middle")
    }
}

assembly loop_sign {
    face_a = sign_face(side=-1)
    face_b = sign_face(side=1)

    solid bracket {
        body = RoundedRectangle(center=(0, 0), width=60, height=H, corner_radius=6)
        mortise = tab_and_slot(part="slot", length=H, thickness=2 * T, tabs=2, tab=40 mm, screw=0,
                               rotation=90 deg, cx=0 mm, cy=0 mm)
        for p in [[-18, -75], [18, -75], [-18, 75], [18, 75]] {
            screw = clearance_hole(size=4, cx=p[0] * 1 mm, cy=p[1] * 1 mm)
        }
        Countersink(screw, diameter=8.4 mm)
    }

    # flat on the sheet
    RightOf(face_b, face_a, gap=10)
    AlignTop(face_b, face_a)
    RightOf(bracket, face_b, gap=10)
    AlignTop(bracket, face_b)

    # assembled: the wall is the plane y = 0, the sign stands out to -y
    Place(bracket, position=(0, 0, 0), face="front", up="up")
    Place(face_a, position=(0, -W / 2, 0), face="left", up="up")
    Place(face_b, position=(0, -W / 2, 0), face="right", up="up")

    # the request's numbers
    assert face_a.body.bb.width == 160 mm and face_a.body.bb.height == 200 mm, "faces 160 x 200"
    assert bracket.body.bb.width == 60 mm and bracket.body.bb.height == 200 mm, "bracket 60 x 200"
    assert bracket.mortise.slot[0].bb.width == 6 mm, "a 6 mm mortise for both faces"
    assert len(bracket.screw) == 4, "four screws"
    assert bracket.screw[1].c.center.x - bracket.mortise.slot[0].bb.center_x == 18 mm, "screws 18 off the mortise"
    assert bracket.screw[2].c.center.y - bracket.body.bb.center_y == 75 mm, "screws 75 above the middle"
    assert face_a.art.name.bb.width <= 135 mm, "HEARING LOOP at most 135 wide"
    assert face_a.art.ear.bb.height >= 80 mm and face_a.art.ear.bb.height <= 95 mm, "ear about 85 tall"
    assert face_a.art.line2.bb.bottom > face_a.art.border.bb.bottom + 2 mm, "text inside the border"
    assert face_a.art.bar.bb.top < face_a.art.border.bb.top - 4 mm, "bar inside the border"
    assert face_a.art.tee.bb.left > face_a.art.ear.bb.right - 6 mm, "T at the ear's lower right"
}
