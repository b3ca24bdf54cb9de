# Request: a "ROUTE 66" highway-shield sign for the garage wall, 300 mm wide and 322 mm tall.
# The back is the US-highway shield outline (two pointed ears at the top with a dipped top
# edge between them, sides that pinch in and swell out, a point at the bottom) in 6 mm ply
# painted black, with two keyholes (8 mm head, 4 mm slot 10 long, upward) 160 mm apart, 95 mm
# above the middle, for screws in the wall. On it a 3 mm white acrylic face: the same outline
# 10 mm smaller all round, leaving a 10 mm black border, with a line engraved across it 70 mm
# above the middle and "ROUTE" engraved filled (28 mm bold letters) in the band above the
# line. On the face two 150 mm bold "6" figures cut from 3 mm black acrylic, glued on, 114 mm
# apart centre to centre, their middle 15 mm below the sign's middle.

units mm

import "std/plates.aidl"

# the outline's box is centred on (0, 0): ears at y 161, the bottom point at -161
shield_pts = [(-150, 161), (-75, 149), (0, 138), (75, 149), (150, 161), (138, 116), (134, 66),
              (145, 6), (140, -54), (110, -109), (55, -142), (0, -161), (-55, -142),
              (-110, -109), (-140, -54), (-145, 6), (-134, 66), (-138, 116)]
shield_corners = [0, 4, 11]

assembly route_sign {
    solid backer {
        thickness 6 mm
        body = Spline(shield_pts, closed=true, corners=shield_corners)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-80 mm,
                         cy=95 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=80 mm,
                         cy=95 mm)
    }

    solid face {
        thickness 3 mm
        outline = Spline(shield_pts, closed=true, corners=shield_corners, construction=true)
        body = Inset(outline, 10)
        drawing band {
            rule = Line((-112, 70), (112, 70))
            word = Text("ROUTE", position=(0, 100), size=28, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    solid six_l {
        thickness 3 mm
        t = Text("6", position=(-57, -15), size=150, font="sans:Bold", valign="middle")
    }
    solid six_r {
        thickness 3 mm
        t = Text("6", position=(57, -15), size=150, font="sans:Bold", valign="middle")
    }

    # flat for cutting
    RightOf(face, backer, gap=10)
    AlignTop(face, backer)
    Below(six_l, backer, gap=10)
    AlignLeft(six_l, backer)
    RightOf(six_r, six_l, gap=10)
    AlignTop(six_r, six_l)

    # assembled: hung on the wall facing the room, face on the backer, figures on the face
    Place(backer, position=(0, 0, 200 mm), face="front", up="up")
    Place(face, on=backer, position=(0, 0))
    Place(six_l, on=face, position=(0, 0))
    Place(six_r, on=face, position=(0, 0))

    assert backer.body.bb.width == 300 mm, "300 wide"
    assert backer.body.bb.height == 322 mm, "322 tall"
    assert backer.body.bb.width - face.body.bb.width >= 20 mm, "at least a 10 mm border"
    assert backer.hang_r.head_hole.center.x - backer.hang_l.head_hole.center.x == 160 mm,
        "keyholes 160 apart"
    assert backer.hang_l.head_hole.center.y - backer.body.bb.center_y == 95 mm, "95 above the middle"
    assert six_r.t.position.x - six_l.t.position.x == 114 mm, "figures 114 apart"
    assert six_l.t.size == 150 mm, "150 mm figures"
    assert six_l.t.position.y - backer.body.bb.center_y == -15 mm, "figures 15 below the middle"
    assert face.band.rule.start.y - backer.body.bb.center_y == 70 mm, "line 70 above the middle"
    assert face.band.word.bb.bottom - face.band.rule.start.y >= 5 mm, "ROUTE above the line"
    assert face.body.bb.top - face.band.word.bb.top >= 5 mm, "ROUTE below the top"
}
