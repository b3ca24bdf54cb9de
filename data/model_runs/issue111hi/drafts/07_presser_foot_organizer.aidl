# Request (crafts): an organizer for twelve snap-on sewing-machine presser feet,
# two plates glued together, 200 x 140 mm with 6 mm rounded corners. The 6 mm
# top plate has 12 pockets (3 rows x 4, 46 mm apart across and 40 mm apart down,
# the grid centred across and its rows at 40, 0 and -40 mm from the plate's
# centre), each 36 x 26 mm with 3 mm corners and a 16 mm round thumb notch
# centred on its top edge; each foot's name is engraved in 4 mm single-stroke
# capitals, no wider than 40 mm, its baseline 7 mm below the pocket. The 3 mm
# base closes the pockets. Both plates have 3 mm holes for alignment pins 8 mm
# in from each corner.

# FIX after the first valid program: each name ran into the thumb notch of the
# pocket below it (W0505 x 8; my assert only measured the first pocket): the
# rows are now 44 mm apart, at 44, 0 and -44 mm, on a plate 150 mm tall.

names = ["ZIGZAG", "OVERCAST", "BLIND HEM", "ZIPPER", "SATIN", "BUTTONHOLE",
         "WALKING", "QUARTER INCH", "DARNING", "ROLLED HEM", "GATHERING", "BUTTON"]

def pin_holes() -> hole {
    c = Circle(center=(0, 0), diameter=3)
}

assembly organizer {
    solid top {
        thickness 6 mm
        plate = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=6)
        hole pocket {
            p = RoundedRectangle(center=(-69, 44), width=36, height=26, corner_radius=3)
            notch = Circle(center=(-69, 57), diameter=16)
        }
        pockets = GridPattern(pocket, 3, 4, (46, -44))
        drawing labels {
            for i in range(12) {
                t = Text(names[i], position=(-69 + (i % 4) * 46, 44 - (i // 4) * 44 - 13 - 7),
                         size=4, max_width=40)
            }
        }
        pins = pin_holes()
        CornerPattern(pins, plate, inset=8)

        assert len(pockets) == 12, "twelve pockets"
        assert len(labels.t) == 12, "a name for every pocket"
        assert abs(pockets[0].bb.center_x + pockets[3].bb.center_x) < 0.01 mm, "grid centred across"
        assert pockets[4].p.center.y - plate.center.y == 0 mm, "middle row on the centre line"
        assert distance(labels, pockets) >= 1 mm, "names clear of every pocket"
        assert distance(labels, pins) >= 2 mm, "names clear of the pin holes"
        assert plate.bb.top - pocket.bb.top >= 5 mm, "material above the top row's notches"
    }

    solid base {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, -170), width=200, height=150, corner_radius=6)
        pins = pin_holes()
        CornerPattern(pins, plate, inset=8)
    }
}
