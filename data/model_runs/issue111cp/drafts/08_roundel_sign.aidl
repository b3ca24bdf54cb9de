# Request (signs): an Underground-style roundel sign "WORKSHOP" for my shed door, from 3 mm
# ply in three layers, painted before gluing:
# - Back disc 300 mm (white): two keyholes (8 mm head, 4 mm slot, 10 mm long, upward) at
#   x = +-80 mm, 90 mm up, hidden behind the ring; engraved filled "EST. 2024" (12 mm) 65 mm
#   above the centre and "MIND THE GAP" (12 mm) 70 mm below it; two 3 mm alignment-pin
#   holes at (0, +-130).
# - Ring (red): 300 mm outside, 220 mm inside, the same two pin holes.
# - Bar (blue): 340 x 60 mm across the middle, 20 mm past the ring each side, "WORKSHOP"
#   cut through it in bold sans stencil letters 34 mm high (the white disc shows through),
#   no wider than 260 mm.

import "std/plates.aidl"

units mm
thickness 3 mm
t = 3 mm

assembly roundel {
    solid back {
        disc = Circle(center=(0, 0), diameter=300)
        # FIX after the first valid program: keyholes cut in the back disc had the ring glued
        # right over them, so no screw head could enter: they move to a hanger strip glued
        # behind the disc, and the disc gets a pocket for each head, hidden behind the ring
        hole relief {
            for x in [-80, 80] {
                s = Slot(center=(x, 95), length=22, width=10, rotation=90 deg)
            }
        }
        hole pins {
            a = Circle(center=(0, 130), diameter=3)
            b = Circle(center=(0, -130), diameter=3)
        }
        drawing words {
            est = Text("EST. 2024", position=(0, 65), size=12, font="sans:Bold", fill=true,
                       valign="middle")
            gap = Text("MIND THE GAP", position=(0, -70), size=12, font="sans:Bold", fill=true,
                       valign="middle")
        }
    }

    solid hanger {
        strip = RoundedRectangle(center=(0, 95), width=200, height=30, corner_radius=5)
        k1 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-80 mm, cy=90 mm)
        k2 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=80 mm, cy=90 mm)
    }

    solid ring {
        outer = Circle(center=(0, 0), diameter=300)
        hole inner { c = Circle(center=(0, 0), diameter=220) }
        hole pins {
            a = Circle(center=(0, 130), diameter=3)
            b = Circle(center=(0, -130), diameter=3)
        }
    }

    solid bar {
        body = Rectangle(center=(0, 0), width=340, height=60)
        hole letters {
            word = Text("WORKSHOP", position=(0, 0), size=34, font="sans:Bold", stencil=true,
                        valign="middle", max_width=260)
        }
    }

    # on the sheet
    RightOf(ring, back, gap=10)
    AlignTop(ring, back)
    Below(bar, back, gap=10)
    AlignLeft(bar, back)
    RightOf(hanger, bar, gap=10)
    AlignTop(hanger, bar)

    # assembled: back, ring, bar stacked and glued
    Place(hanger, position=(0, 0, -t))
    Place(back, position=(0, 0, 0))
    Place(ring, position=(0, 0, t))
    Place(bar, position=(0, 0, 2 * t))

    assert back.disc.diameter == 300 mm, "300 mm disc"
    assert ring.outer.diameter == 300 mm and ring.inner.c.diameter == 220 mm, "ring 300 / 220"
    assert bar.body.width == 340 mm and bar.body.height == 60 mm, "bar 340 x 60"
    assert (bar.body.width - ring.outer.diameter) / 2 == 20 mm, "20 mm past the ring"
    assert bar.letters.word.bb.width <= 260 mm, "lettering at most 260 wide"
    assert bar.letters.word.bb.top < bar.body.bb.top and bar.letters.word.bb.bottom > bar.body.bb.bottom, "letters on the bar"
    assert hanger.k1.head_hole.center.y == 90 mm and hanger.k2.head_hole.center.x == 80 mm, "keyholes"
    # the head (8 mm) at the slot's end reaches 2 mm past the 4 mm slot's top
    assert back.relief.s[0].bb.bottom < hanger.k1.head_hole.bb.bottom and back.relief.s[0].bb.top > hanger.k1.slot.bb.top + 2 mm, "head pockets cover the keyholes"
}
