# Request (music): a soundhole cover (feedback buster) for my acoustic guitar, whose soundhole
# is 100 mm across, from 3 mm birch ply, three parts glued in a stack:
# - a plug ring that fits the soundhole: 99.6 mm outside (0.4 mm clearance), 84 mm inside;
# - a cap 112 mm across that rests on the guitar top, its edge scalloped: a 104 mm disc with
#   24 bumps 8 mm across whose centres sit on its rim; engraved on it: two rings 96 mm and
#   76 mm across, "ELLIE'S MARTIN" over the top and "NO FEEDBACK" under the bottom (5 mm,
#   between the two rings, both reading left to right), and a ring of 12 five-point stars
#   6 mm across on a 54 mm circle;
# - a lifting knob on the middle: a six-point star 32 mm across with 3 mm rounded tips,
#   notches 24 mm across.

import "std/plates.aidl"

thickness 3 mm
t = 3 mm
soundhole = 100 mm

assembly cover {
    solid plug {
        ring = Circle(center=(0, 0), diameter=soundhole - 0.4 mm)
        Fixed(ring)
        hole bore { c = Circle(center=(0, 0), diameter=84 mm) }
    }

    solid cap {
        disc = Circle(center=(0, 0), diameter=104 mm)
        Fixed(disc)
        for i in range(24) {
            bump = Circle(center=(52 mm * cos(i * 15 deg), 52 mm * sin(i * 15 deg)),
                          diameter=8 mm)
        }
        drawing rings {
            outer = Circle(center=(0, 0), diameter=96 mm)
            inner = Circle(center=(0, 0), diameter=76 mm)
            top_base = Circle(center=(0, 0), radius=40 mm, construction=true)
            bottom_base = Circle(center=(0, 0), radius=45 mm, construction=true)
            name = Text("ELLIE'S MARTIN", along=top_base, size=5)
            motto = Text("NO FEEDBACK", along=bottom_base, size=5, flip=true)
        }
        drawing stars {
            s = Star(center=(0, 27 mm), points=5, outer_radius=3 mm, inner_radius=1.3 mm)
            all = CircularPattern(s, 12, (0, 0))
        }
    }

    solid knob {
        grip = Star(center=(0, 0), points=6, outer_radius=16 mm, inner_radius=12 mm,
                    tip_radius=3 mm)
        Fixed(grip)
    }

    # flat on the sheet
    RightOf(plug, cap, gap=10)
    AlignCenterY(plug, cap)
    RightOf(knob, plug, gap=10)
    AlignCenterY(knob, plug)

    # in 3D: the plug ring in the soundhole, the cap on it, the knob on the cap
    Place(plug, position=(0, 0, 0))
    Place(cap, position=(0, 0, t))
    Place(knob, position=(0, 0, 2 * t))

    # the request's numbers
    assert plug.ring.diameter == 99.6 mm and plug.bore.c.diameter == 84 mm, "plug 99.6 / 84"
    assert soundhole - plug.ring.diameter == 0.4 mm, "0.4 mm clearance in the soundhole"
    assert cap.bb.width == 112 mm and cap.bb.height == 112 mm, "cap 112 across"
    assert len(cap.bump) == 24, "24 bumps"
    assert cap.bb.width - plug.ring.diameter >= 10 mm, "the cap overlaps the guitar top"
    assert len(cap.stars.all) == 12, "12 stars"
    assert distance(cap.rings.name, cap.rings.outer) >= 1 mm and
        distance(cap.rings.name, cap.rings.inner) >= 1 mm, "name between the rings"
    assert distance(cap.rings.motto, cap.rings.outer) >= 1 mm and
        distance(cap.rings.motto, cap.rings.inner) >= 1 mm, "motto between the rings"
    assert distance(cap.stars, cap.rings.inner) >= 2 mm, "stars inside the inner ring"
    assert 27 mm - 3 mm >= 16 mm + 2 mm, "stars clear of the knob"
    assert knob.grip.bb.height <= 32 mm, "knob 32 across"
}
