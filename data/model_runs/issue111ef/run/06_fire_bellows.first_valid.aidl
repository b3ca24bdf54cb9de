# Request (camping): hand bellows for the camp fire, 6 mm plywood (the leather gusset and
# the intake flap are not cut).
# - Two boards, pear-shaped: a 200 mm circle and an 80 mm round nose whose centre is 150 mm
#   ahead of the big circle's, joined by straight sides; a handle 50 wide and 120 long,
#   R20 corners, centred 150 mm behind the big circle's centre, with a 12 mm hanging hole
#   190 mm behind it.
# - The bottom board has a 40 mm air intake hole at the big circle's centre.
# - The top board is engraved STOKE, filled, bold sans 24 mm, centred 20 mm ahead of the
#   big circle's centre.
# - A nozzle 125 mm long, 60 mm wide at its back end and 24 mm at the tip, its back end
#   60 mm inside the boards' nose: three layers, a plate, two rails leaving a 12 mm air
#   channel along its whole length, and a plate; glued between the boards.

thickness 6 mm

def board(intake=false, label=false) -> solid {
    body = Hull(Circle(center=(0, 0), radius=100), Circle(center=(0, 150), radius=40))
    grip = RoundedRectangle(center=(0, -150), width=50, height=120, corner_radius=20)
    hole hang { h = Circle(center=(0, -190), diameter=12) }
    if intake {
        hole air { a = Circle(center=(0, 0), diameter=40) }
    }
    if label {
        drawing name {
            t = Text("STOKE", position=(0, 20), size=24, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

def nozzle_plate() -> solid {
    t = Trapezoid(center=(0, 192.5), bottom_width=60, top_width=24, height=125)
}

assembly bellows {
    top = board(label=true)
    bottom = board(intake=true)
    plate_low = nozzle_plate()
    plate_high = nozzle_plate()
    solid rail_left {
        p = Polygon([(-30, 130), (-6, 130), (-6, 255), (-12, 255)])
    }
    solid rail_right {
        p = Polygon([(6, 130), (30, 130), (12, 255), (6, 255)])
    }

    # flat on the sheet
    RightOf(bottom, top, gap=10)
    AlignTop(bottom, top)
    RightOf(plate_low, bottom, gap=10)
    AlignTop(plate_low, bottom)
    RightOf(plate_high, plate_low, gap=10)
    AlignTop(plate_high, plate_low)
    Below(rail_left, plate_low, gap=10)
    AlignLeft(rail_left, plate_low)
    Below(rail_right, plate_high, gap=10)
    AlignLeft(rail_right, plate_high)

    # in 3D, lying flat, the nozzle's layers between the boards
    Place(bottom, position=(0, 0, 0), face="up", up="back")
    Place(plate_low, position=(0, 0, 6), face="up", up="back")
    Place(rail_left, position=(0, 0, 12), face="up", up="back")
    Place(rail_right, position=(0, 0, 12), face="up", up="back")
    Place(plate_high, position=(0, 0, 18), face="up", up="back")
    Place(top, position=(0, 0, 24), face="up", up="back")

    assert top.body.bb.width == 200 mm, "200 mm body"
    assert top.body.bb.top - top.body.bb.bottom == 100 mm + 150 mm + 40 mm, "nose 150 ahead"
    assert top.grip.width == 50 mm and top.grip.height == 120 mm, "handle 50 x 120"
    assert top.grip.center.y == -150 mm, "handle centred 150 behind"
    assert top.hang.h.center.y == -190 mm, "hanging hole 190 behind"
    assert bottom.air.a.diameter == 40 mm, "40 mm intake"
    assert plate_low.t.height == 125 mm and plate_low.t.bottom_width == 60 mm and
        plate_low.t.top_width == 24 mm, "nozzle 125 long, 60 to 24"
    assert top.body.bb.top - plate_low.t.bb.bottom == 60 mm, "nozzle 60 inside the nose"
    assert rail_right.p.points[0].x - rail_left.p.points[1].x == 12 mm, "12 mm channel"
}
