# Request: a round infinity mirror for the wall above my desk, 250 mm across, four laser-cut
# layers held by four M3 bolts on a 236 mm circle (3.4 mm holes in every layer):
# - bezel, 3 mm black acrylic: a ring 250 / 196 mm (its lip hides the LED strip), the bolt
#   holes countersunk 6.5 mm for M3 flat heads;
# - front glass, 3 mm clear acrylic (one-way mirror film goes on it): a full 250 mm disc;
# - spacer, 12 mm ply: a ring 250 / 206 mm, the LED strip (60 LEDs/m, 38 LEDs) stuck round
#   its inside; a 6 mm notch through it on the left for the cable; a 10 mm wide clearance
#   slot over the keyhole for the screw head; "5 V  38 LEDS" engraved along the bottom of
#   its back face;
#   FIX after the first valid program: the spacer's back face lies on the rear mirror, so
#   the label could never be seen (note W0532 said so of the front face, where the first
#   valid program put it); the label moves to the rear mirror's back (wall side);
# - rear mirror, 3 mm mirror acrylic: a full 250 mm disc, with a keyhole at the top (8 mm
#   head, 4 mm slot 6 mm long, pointing up) 114 mm above the centre, hidden behind the spacer.

units mm
import "std/shapes.aidl"
import "std/plates.aidl"

od = 250 mm
pcd = 236 mm
bolt_d = 3.4 mm

assembly infinity {
    solid bezel {
        thickness 3 mm
        disc = Circle(center=(0, 0), diameter=od)
        hole window { c = Circle(center=(0, 0), diameter=196) }
        bolts = bolt_circle(count=4, pcd=pcd, hole_d=bolt_d, start=45 deg)
        Countersink(bolts, diameter=6.5)
    }

    solid glass {
        thickness 3 mm
        disc = Circle(center=(0, 0), diameter=od)
        bolts = bolt_circle(count=4, pcd=pcd, hole_d=bolt_d, start=45 deg)
    }

    solid spacer {
        thickness 12 mm
        disc = Circle(center=(0, 0), diameter=od)
        hole bore { c = Circle(center=(0, 0), diameter=206) }
        bolts = bolt_circle(count=4, pcd=pcd, hole_d=bolt_d, start=45 deg)
        hole cable { r = Rectangle(center=(-114, 0), width=24, height=6) }
        hole head_room { s = Slot(start=(0, 112), end=(0, 118), width=10) }
    }

    solid mirror {
        thickness 3 mm
        disc = Circle(center=(0, 0), diameter=od)
        bolts = bolt_circle(count=4, pcd=pcd, hole_d=bolt_d, start=45 deg)
        hang = keyhole(head=8, slot_width=4, length=6, direction=90 deg, cx=0, cy=114)
        drawing label {
            ring = Circle(center=(0, 0), radius=118, construction=true)
            t = Text("5 V  38 LEDS", along=ring, size=5, flip=true)
        }
    }

    # flat on the sheet in a row; stacked on the wall, the mirror at the back
    RightOf(glass, bezel, gap=10)
    RightOf(spacer, glass, gap=10)
    RightOf(mirror, spacer, gap=10)
    AlignCenterY(glass, bezel)
    AlignCenterY(spacer, bezel)
    AlignCenterY(mirror, bezel)
    # its engraved face (the label) looks at the wall: face down, its bottom face at z 3
    Place(mirror, position=(0, 0, 3), face="down")
    Place(spacer, position=(0, 0, 3))
    Place(glass, position=(0, 0, 15))
    Place(bezel, position=(0, 0, 18))

    # the request's numbers
    assert bezel.disc.diameter == 250 mm and glass.disc.diameter == 250 mm and
        spacer.disc.diameter == 250 mm and mirror.disc.diameter == 250 mm, "250 mm layers"
    assert bezel.window.c.diameter == 196 mm, "bezel ring 250 / 196"
    assert spacer.bore.c.diameter == 206 mm, "spacer ring 250 / 206"
    assert len(bezel.bolts.bolt) == 4 and len(mirror.bolts.bolt) == 4, "four M3 bolts"
    assert bezel.bolts.bolt[0].diameter == 3.4 mm, "3.4 mm bolt holes"
    assert abs(distance(spacer.bolts.bolt[0].center, spacer.disc.center) - 118 mm) < 0.01 mm,
        "bolts on a 236 mm circle"
    assert bezel.window.c.diameter < spacer.bore.c.diameter, "the bezel's lip hides the strip"
    assert mirror.hang.head_hole.center.y - mirror.disc.center.y == 114 mm,
        "keyhole 114 mm above the centre"
    assert mirror.hang.head_hole.diameter == 8 mm, "8 mm keyhole head"
    # the keyhole lies behind the spacer's ring, under its clearance slot
    assert distance(mirror.hang.head_hole.center, mirror.disc.center) - 8 mm / 2 >=
        206 mm / 2 + 2 mm, "keyhole behind the spacer ring, not in the mirror's view"
    assert spacer.head_room.bb.bottom - spacer.disc.center.y <= 114 mm - 8 mm / 2,
        "head room covers the keyhole's head"
    assert spacer.head_room.bb.top - spacer.disc.center.y >= 114 mm + 6 mm + 4 mm / 2,
        "head room covers the keyhole's slot"
    assert spacer.cable.r.height == 6 mm, "6 mm cable notch"
    assert spacer.cable.bb.left <= spacer.disc.bb.left and
        spacer.cable.bb.right >= spacer.disc.center.x - 206 mm / 2, "the notch runs through the ring"
    assert distance(mirror.label, mirror.bolts) >= 2 mm, "label clear of the bolts"
    assert distance(mirror.label.t.center, mirror.disc.center) >= 206 mm / 2,
        "label behind the spacer ring"
}
