# Request: a perpetual club-champion shield for our tennis club. A heater shield 200 mm
# wide: straight sides 130 mm high from the shoulders (y = 0) to the flat top, and below them
# a point made by two 130 mm-radius arcs (centres 30 mm either side of the middle, so they
# meet the sides tangentially). Two layers glued: a 3 mm walnut-veneer front engraved with
# "CLUB CHAMPION" (filled bold, at most 180 wide), "RIVERSIDE TENNIS CLUB", a tennis ball
# (36 mm, two seams) and ten 70 x 14 mm plate outlines (r2) in 2 columns 80 mm apart x 5
# rows 20 mm apart; a 6 mm ply back layer 4 mm smaller all round with a keyhole (hidden by
# the front) to hang it. And the first name plate, 1.5 mm gold acrylic 70 x 14 r2,
# "2026  A. OKAFOR" engraved, which sits on the top-left outline.

import "std/plates.aidl"

W = 200 mm
H_top = 130 mm
R = 130 mm
c = 30 mm
margin = 4 mm

assembly shield {
    solid front {
        thickness 3 mm
        top = Rectangle(bottom_left=(-W / 2, 0), width=W, height=H_top)
        point = Intersect(Circle(center=(-c, 0), radius=R), Circle(center=(c, 0), radius=R))
        drawing art {
            title = Text("CLUB CHAMPION", (0, 108), size=12, font="sans:Bold", fill=true,
                         max_width=180)
            club = Text("RIVERSIDE TENNIS CLUB", (0, 92), size=6)
            ball = Circle(center=(0, 60), radius=18)
            seam_l = Intersect(Circle(center=(0, 60), radius=18),
                               Arc(center=(-30, 60), radius=24, start_angle=-50 deg,
                                   end_angle=50 deg))
            seam_r = Intersect(Circle(center=(0, 60), radius=18),
                               Arc(center=(30, 60), radius=24, start_angle=130 deg,
                                   end_angle=230 deg))
            slot = RoundedRectangle(center=(-40, 22), width=70, height=14, corner_radius=2)
            slots = GridPattern(slot, 5, 2, (80 mm, -20 mm))
        }
    }

    solid back {
        thickness 6 mm
        top = Rectangle(bottom_left=(-W / 2 + margin, 0), width=W - 2 * margin,
                        height=H_top - margin)
        point = Intersect(Circle(center=(-c, 0), radius=R - margin),
                          Circle(center=(c, 0), radius=R - margin))
        hang = keyhole(cx=0 mm, cy=95 mm)
    }

    solid plate {
        thickness 1.5 mm
        body = RoundedRectangle(center=(0, 0), width=70, height=14, corner_radius=2)
        drawing name {
            t = Text("2026  A. OKAFOR", (0, 0), size=5, valign="middle")
        }
    }

    # flat on the sheet
    RightOf(back, front, gap=10)
    AlignTop(back, front)
    Below(plate, back, gap=10)
    AlignCenterX(plate, back)

    # in 3D: back on the wall, front on it, the plate on the top-left outline
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 6))
    Place(plate, position=(-40, 22, 9))

    assert front.bb.width == 200 mm, "200 wide"
    assert front.top.bb.height == 130 mm, "sides 130 high"
    assert len(front.art.slots) == 10, "ten plates"
    assert front.art.slots[1].center.x - front.art.slots[0].center.x == 80 mm, "columns 80"
    assert front.art.slots[0].center.y - front.art.slots[2].center.y == 20 mm, "rows 20"
    assert front.bb.width - back.bb.width == 2 * 4 mm, "back 4 mm smaller"
    assert plate.body.bb.width == 70 mm and plate.body.bb.height == 14 mm, "plate 70 x 14"
}
