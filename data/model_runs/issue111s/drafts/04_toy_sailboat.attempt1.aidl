# Toy: a flat-pack sailboat in 4 mm plywood. Deck (top view) 160 mm long, 50 mm wide: a square
# stern, straight sides to 110 mm, then a pointed bow. The sail is a right triangle 70 mm along
# its foot and 100 mm up the mast edge; it stands on the deck's centre line, its foot
# (40 mm from the stern to 110 mm) glued into the deck by two 10 mm tabs in mortises (glued,
# no screws, 0.1 mm clearance). A 6 mm pull-string hole 15 mm behind the bow tip. The boat's
# name "SEA BEE" engraved 6 mm on the sail, 15 mm above the foot.

import "std/joints.aidl"

thickness 4 mm

assembly sailboat {
    solid deck {
        body = Polygon([(0, -25), (110, -25), (160, 0), (110, 25), (0, 25)])
        mortise = tab_and_slot(part="slot", length=70 mm, thickness=4 mm, tabs=2, tab=10 mm,
                               screw=0, clearance=0.1 mm, cx=75 mm, cy=0 mm)
        hole pull {
            c = Circle(center=(145, 0), diameter=6)
        }
    }
    solid sail {
        body = Polygon([(0, 0), (70, 0), (0, 100)])
        foot = tab_and_slot(part="tab", length=70 mm, thickness=4 mm, tabs=2, tab=10 mm,
                            screw=0, cx=35 mm, cy=4 mm)
        drawing name {
            t = Text("SEA BEE", (25, 15), size=6)
        }
        name.bb.bottom == body.bb.bottom + 15
        name.bb.left == body.bb.left + 5
    }
    Above(sail, deck, gap=10)

    assert deck.body.bb.width == 160 mm and deck.body.bb.height == 50 mm, "deck 160 x 50"
    assert sail.body.bb.width == 70 mm and sail.body.bb.height == 100 mm, "sail 70 x 100"
    assert deck.pull.c.center.x == deck.body.bb.right - 15 mm, "pull hole 15 behind the bow"
    assert deck.mortise.slot.bb.left >= deck.body.bb.left + 40 mm, "slots within 40..110"
    assert deck.mortise.slot.bb.right <= deck.body.bb.left + 110 mm, "slots within 40..110"
    assert sail.name.bb.bottom - sail.body.bb.bottom == 15 mm, "name 15 up"
    assert sail.name.bb.right < 70 mm * (1 - 21 / 100) + sail.body.bb.left, "name inside the sail's slope"
}
