# Request (sport): "A handlebar route-card holder for sportives and audax rides. Three layers
# screwed together with four M3 screws, 5 mm in from the edges at the corners; each layer
# 120 x 80 mm with R6 corners:
# - back (3 mm acrylic), with a mounting tongue 48 mm wide and 45 mm tall below it (R6 bottom
#   corners, R4 where it meets the plate) carrying two pairs of 12 x 4.5 mm zip-tie slots:
#   slots lying across, 24 mm apart side to side, 36 mm apart up and down (around a 31.8 mm bar);
# - spacer (2 mm), a U frame: the pocket for the 100 x 65 mm route card is the card plus 0.5 mm
#   each way, open at the top so the card slides in from above, 7 mm of frame under it;
# - clear cover (2 mm) with an R10 thumb notch in the middle of its top edge.
# Engrave 'ROUTE' on the spacer's bottom bar, and the rider's name 'K. MARSH' on the tongue between
# the tie slots."

units mm
thickness 2 mm

import "std/fasteners.aidl"

plate_w = 120 mm
plate_h = 80 mm
card_w = 100 mm
card_h = 65 mm
pocket_w = card_w + 1 mm
pocket_h = card_h + 1 mm

def layer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6)
    screw = clearance_hole(size=3)
    screws = CornerPattern(screw, body, inset=5)
}

assembly route_card_holder {
    solid back {
        thickness 3 mm
        plate = layer()
        tongue = RoundedRectangle(center=(0, -plate_h / 2 - 22.5 + 3), width=48, height=51,
                                  corner_radii=[0, 0, 6, 6])
        Fillet([tongue, plate.body], 4)
        hole ties {
            for r in range(2) {
                for c in range(2) {
                    s = Slot(center=(-12 + 24 * c, -plate_h / 2 - 22.5 - 18 + 36 * r), length=12,
                             width=4.5)
                }
            }
        }
        drawing name {
            n = Text("K. MARSH", position=(0, -plate_h / 2 - 22.5), size=4, valign="middle")
        }
        assert plate.body.bb.bottom - tongue.bb.bottom == 45 mm, "tongue 45 below the plate"
        assert tongue.bb.width == 48 mm, "tongue 48 wide"
        assert ties.s[1][0].center.y - ties.s[0][0].center.y == 36 mm, "ties 36 apart up/down"
        assert ties.s[0][1].center.x - ties.s[0][0].center.x == 24 mm, "ties 24 apart across"
        assert distance(name, ties) >= 1 mm, "name clear of the tie slots"
    }

    solid spacer {
        plate = layer()
        hole pocket {
            r = Rectangle(bottom_left=(-pocket_w / 2, -plate_h / 2 + 7), width=pocket_w,
                          height=plate_h)
        }
        drawing word {
            w = Text("ROUTE", position=(0, -plate_h / 2 + 3.5), size=3.5, valign="middle")
        }
        assert pocket.r.bb.bottom - plate.body.bb.bottom == 7 mm, "7 mm of frame under the card"
        assert pocket.r.bb.width == 101 mm, "pocket = card + 0.5 each side"
        assert distance(pocket, plate.screws[0]) >= 1 mm, "frame holds the screws"
        assert distance(word, pocket) >= 0.5 mm, "ROUTE on the bottom bar"
    }

    solid cover {
        plate = layer()
        hole thumb {
            c = Circle(center=(0, plate_h / 2), radius=10)
        }
    }

    RightOf(spacer, back, gap=8)
    AlignTop(spacer, back)
    RightOf(cover, spacer, gap=8)
    AlignTop(cover, spacer)
}
