# Request (science, a school's pond study): a Secchi disk kit for measuring water clarity,
# two parts, 6 mm thick.
# - Disk: 200 mm across, white acrylic, a 10 mm centre hole for an M10 eyebolt (the weight
#   hangs beneath it). Two opposite quadrants (0-90 and 180-270 deg) engraved filled, to be
#   painted black, from 7 mm round the centre out to 0.5 mm inside the rim.
# - Line winder: birch ply, 220 x 90 mm with 10 mm corner radii; a round-ended notch 30 mm
#   wide and 25 mm deep in the middle of each end for the line; a 90 x 25 mm hand slot in
#   the middle; a jam slit for the line's end, cut 15 mm long from the left end, 30 mm below
#   the centre line, sloping down at 20 deg; "SECCHI DISK LINE" above the hand slot and
#   "10 m, MARKED EVERY 0.5 m" below it, 6 mm letters centred 25 mm above and below the
#   centre line.
# Laid out side by side, 10 mm apart.

units mm
thickness 6 mm

assembly secchi_kit {
    solid disk {
        plate = Circle(center=(0, 0), diameter=200)
        hole eye { c = Circle(center=(0, 0), diameter=10) }
        drawing quadrants {
            q1 = Sector(center=(0, 0), radius=99.5, inner_radius=7, start_angle=0 deg, end_angle=90 deg, fill=true)
            q3 = Sector(center=(0, 0), radius=99.5, inner_radius=7, start_angle=180 deg, end_angle=270 deg, fill=true)
        }
    }

    solid winder {
        board = RoundedRectangle(center=(0, 0), width=220, height=90, corner_radius=10)
        hole notches {
            right = Slot(center=(110, 0), length=50, width=30)
            left = Slot(center=(-110, 0), length=50, width=30)
        }
        hole hand { s = Slot(center=(0, 0), length=90, width=25) }
        cut jam { slit = Line((-110, -30), length=15, angle=-20 deg) }
        drawing words {
            top = Text("SECCHI DISK LINE", position=(0, 25), size=6, valign="middle")
            bottom = Text("10 m, MARKED EVERY 0.5 m", position=(0, -25), size=6, valign="middle")
        }
    }

    RightOf(winder, disk, gap=10)
    AlignCenterY(winder, disk)

    # the request's numbers
    assert disk.plate.diameter == 200 mm, "disk 200"
    assert disk.eye.c.diameter == 10 mm, "10 mm eye"
    assert disk.quadrants.q1.inner_radius == 7 mm and disk.quadrants.q1.radius == 99.5 mm, "7 mm to 0.5 inside the rim"
    assert winder.board.width == 220 mm and winder.board.height == 90 mm, "winder 220 x 90"
    assert winder.notches.right.width == 30 mm, "notch 30 wide"
    assert winder.board.bb.right - (winder.notches.right.center.x - winder.notches.right.length / 2) == 25 mm, "notch 25 deep"
    assert winder.hand.s.length == 90 mm and winder.hand.s.width == 25 mm, "hand slot 90 x 25"
    assert winder.jam.slit.length == 15 mm, "jam slit 15"
    assert winder.jam.slit.start.x == winder.board.bb.left, "jam slit from the left end"
    assert winder.board.center.y - winder.jam.slit.start.y == 30 mm, "30 below the centre line"
    assert winder.words.top.position.y - winder.board.center.y == 25 mm, "25 above"
    assert winder.board.center.y - winder.words.bottom.position.y == 25 mm, "25 below"
    assert distance(winder.words, winder.hand) >= 2 mm and distance(winder.words, winder.notches) >= 2 mm, "words clear of the slots"
    assert winder.bb.left - disk.bb.right == 10 mm, "10 apart"
}
