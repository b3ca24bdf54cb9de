# Request (toys): a wind-powered toy land yacht (a three-wheeled sand yacht) from 3 mm ply,
# with a sail cut from 0.8 mm polypropylene on the same laser.
# - Deck: a tapered board 220 mm long, 120 mm wide at the rear, 40 mm at the nose, 6 mm
#   rounded corners; an 8.2 mm hole for an 8 mm dowel mast 130 mm from the rear edge; the name
#   "BREEZE" (10 mm bold, filled) engraved along the centre line, its middle 75 mm from the rear.
# - Four axle hangers under the deck, each 60 mm long and hanging 45 mm below the deck, glued
#   into the deck with two 12 mm tabs each: the rear pair 45 mm either side of the centre line,
#   the front pair 5 mm either side, centred 35 mm and 185 mm from the rear edge. Each hanger
#   has a 5.5 mm hole for a 5 mm dowel axle 10 mm above its bottom edge (35 mm below the deck),
#   so the 60 mm wheels run 5 mm clear of the deck's underside.
# - Three 60 mm wheels with a 4.9 mm press-fit bore and three 14 mm lightening holes on a
#   32 mm circle; the rear wheels outside the rear hangers with 1 mm for a washer, the front
#   wheel centred between the front hangers.
# - A triangular sail: luff 200 mm up the mast, foot 120 mm back along the deck, 15 mm above the
#   deck; five 4 mm lacing holes 8 mm in from the luff, 35 mm apart from 20 mm up; the sail
#   number "7" 30 mm tall engraved filled.

units mm
thickness 3 mm
import "std/joints.aidl"

def hanger() -> solid {
    # the tabs' tips on y = 0; the deck's underside at y = -3
    body = Rectangle(center=(0, -24), width=60, height=48)
    tabs = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm, screw=0,
                        cx=0 mm, cy=0 mm)
    hole axle { c = Circle(center=(0, -38), diameter=5.5) }
}

def wheel() -> solid {
    rim = Circle(center=(0, 0), diameter=60)
    hole bore { c = Circle(center=(0, 0), diameter=4.9) }
    hole window { w = Circle(center=(0, 16), diameter=14) }
    windows = CircularPattern(window, 3, (0, 0))
}

# where the parts stand in 3D: (x of the bottom face, y along the deck, z)
hx = [43.5, -46.5, 3.5, -6.5]
hy = [35, 35, 185, 185]
wx = [47.5, -50.5, -1.5]
wy = [35, 35, 185]

assembly yacht {
    solid deck {
        body = Trapezoid(center=(0, 110), bottom_width=120, top_width=40, height=220)
        Fillet(body, 6)
        for i in range(4) {
            seat = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg,
                                cx=hx[i] + 1.5 mm, cy=hy[i])
        }
        hole mast { c = Circle(center=(0, 130), diameter=8.2) }
        drawing name {
            t = Text("BREEZE", position=(0, 75), size=10, font="sans:Bold", valign="middle",
                     rotation=90, fill=true)
        }
    }
    Place(deck, position=(0, 0, 0))

    for i in range(4) {
        h = hanger()
        h.bb.center == (120, 30 + 55 * i)
        Place(h, position=(hx[i], hy[i], 3), face="right", up="up")
    }

    for i in range(3) {
        w = wheel()
        w.bb.center == (200, 30 + 70 * i)
        Place(w, position=(wx[i], wy[i], 3 - 38), face="right", up="up")
    }

    solid sail {
        thickness 0.8 mm
        body = Polygon([(0, 0), (0, 200), (120, 0)])
        for k in range(5) {
            hole lace { c = Circle(center=(8, 20 + 35 * k), diameter=4) }
        }
        drawing number {
            n = Text("7", position=(40, 50), size=30, font="sans:Bold", valign="middle", fill=true)
        }
    }
    sail.bb.center == (-160, 110)
    # luff 5 mm behind the mast's centre, the foot running back (drawing +x is the yacht's -y)
    Place(sail, position=(0.4, 125, 3 + 15), face="left", up="up")

    # the request's numbers
    assert deck.body.height == 220 mm and deck.body.bottom_width == 120 mm and deck.body.top_width == 40 mm,
        "deck 220 long, 120 to 40 wide"
    assert deck.mast.c.center.y - deck.body.bb.bottom == 130 mm, "mast 130 mm from the rear"
    assert deck.name.t.position.y - deck.body.bb.bottom == 75 mm, "name centred 75 mm from the rear"
    assert deck.seat[0].bb.center_y - deck.body.bb.bottom == 35 mm, "rear hangers 35 mm from the rear"
    assert deck.seat[2].bb.center_y - deck.body.bb.bottom == 185 mm, "front hangers 185 mm from the rear"
    assert deck.seat[0].bb.center_x - deck.body.center.x == 45 mm, "rear hangers 45 mm off the centre line"
    assert deck.seat[2].bb.center_x - deck.body.center.x == 5 mm, "front hangers 5 mm off the centre line"
    assert len(h) == 4 and len(w) == 3, "four hangers, three wheels"
    assert (h[0].body.bb.top - 3 mm) - h[0].body.bb.bottom == 45 mm, "hangers 45 mm below the deck"
    assert h[0].axle.c.center.y - h[0].body.bb.bottom == 10 mm, "axle 10 mm above the hanger's bottom"
    assert (h[0].body.bb.top - 3 mm) - h[0].axle.c.center.y - w[0].rim.radius == 5 mm,
        "wheels 5 mm clear of the deck"
    assert w[0].rim.diameter == 60 mm, "60 mm wheels"
    assert wx[0] - (hx[0] + 3 mm) == 1 mm, "1 mm washer gap at the rear wheels"
    assert (hx[2] - (wx[2] + 3 mm)) == (wx[2] - (hx[3] + 3 mm)), "front wheel centred between its hangers"
    assert sail.body.bb.height == 200 mm and sail.body.bb.width == 120 mm, "sail luff 200, foot 120"
    assert sail.lace[1].c.center.y - sail.lace[0].c.center.y == 35 mm, "lacing holes 35 apart"
    assert sail.lace[0].c.center.x - sail.body.bb.left == 8 mm, "lacing holes 8 mm in"
    assert len(sail.lace) == 5, "five lacing holes"
}
