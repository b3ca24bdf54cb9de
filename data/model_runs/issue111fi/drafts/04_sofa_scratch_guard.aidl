# Request (pets): a guard that wraps the front corner of the sofa arm so the cat scratches
# the post, not the sofa. One piece of 3 mm birch ply, 450 x 400 mm flat, top corners
# rounded 20 mm: a 150 mm front face, a 50 mm living-hinge band (pitch 2, cuts 15 mm,
# bridges 3 mm) that bends 90 degrees round the arm's corner, and a 250 mm side face.
# 3 mm holes for upholstery twist pins, 12 mm in from both end edges, 6 a side, 64 mm
# apart starting 40 mm up. On the front face, engraved filled: a cat's paw print (pad
# 44 x 36 mm, four toes 16 x 20 mm) and "NO CLAWS" (sans bold, at most 110 mm wide).

units mm
thickness 3 mm
import "std/plates.aidl"

W = 450 mm
H = 400 mm
FRONT = 150 mm
HINGE = 50 mm
T = 3 mm
R_BEND = HINGE / (pi / 2) - T / 2

assembly guard_kit {
    solid guard {
        body = RoundedRectangle(bottom_left=(0, 0), width=W, height=H,
                                corner_radii=[20, 20, 0, 0])
        flex = living_hinge(width=HINGE, height=H, pitch=2 mm, cut=15 mm, bridge=3 mm,
                            cx=FRONT + HINGE / 2, cy=H / 2)
        hole pins {
            for k in range(6) {
                l = Circle(center=(12, 40 + k * 64), diameter=3)
                r = Circle(center=(W - 12, 40 + k * 64), diameter=3)
            }
        }
        drawing paw {
            pad = Ellipse(center=(75, 265), rx=22, ry=18, fill=true)
            t1 = Ellipse(center=(45, 295), rx=8, ry=10, rotation=20 deg, fill=true)
            t2 = Ellipse(center=(63, 310), rx=8, ry=10, rotation=5 deg, fill=true)
            t3 = Ellipse(center=(87, 310), rx=8, ry=10, rotation=-5 deg, fill=true)
            t4 = Ellipse(center=(105, 295), rx=8, ry=10, rotation=-20 deg, fill=true)
        }
        drawing words {
            t = Text("NO CLAWS", position=(75, 200), size=14, font="sans:Bold",
                     valign="middle", max_width=110, fill=true)
        }
        Fixed(body)
    }
    # standing in front of the arm, the side face bent back along it
    Place(guard, position=(0, 0, 0), face="front", up="up")
    Bend(guard, at=FRONT + HINGE / 2, angle=-90 deg, radius=R_BEND)

    assert guard.body.bb.width == 450 mm and guard.body.bb.height == 400 mm, "450 x 400"
    assert guard.flex.width == 50 mm, "50 mm hinge band"
    assert guard.flex.bb.left >= guard.body.bb.left + 150 mm - 1 mm, "front face 150"
    assert guard.body.bb.right - guard.flex.bb.right >= 250 mm - 1 mm, "side face 250"
    assert 90 deg * pi / 180 deg * (R_BEND + T / 2) == 50 mm, "the bend uses the band"
    assert len(guard.pins.l) == 6 and len(guard.pins.r) == 6, "6 pins a side"
    assert guard.pins.l[0].center.x - guard.body.bb.left == 12 mm, "pins 12 in"
    assert guard.body.bb.right - guard.pins.r[0].center.x == 12 mm, "pins 12 in"
    assert guard.pins.l[1].center.y - guard.pins.l[0].center.y == 64 mm, "pins 64 apart"
    assert guard.pins.l[0].center.y - guard.body.bb.bottom == 40 mm, "first pin 40 up"
    assert guard.paw.pad.rx * 2 == 44 mm and guard.paw.pad.ry * 2 == 36 mm, "pad size"
    assert guard.words.bb.width <= 110 mm, "words at most 110 wide"
    assert guard.paw.bb.right <= guard.body.bb.left + 150 mm - 10 mm, "paw on the front face"
    assert guard.words.bb.right <= guard.body.bb.left + 150 mm - 10 mm, "words on the front face"
}
