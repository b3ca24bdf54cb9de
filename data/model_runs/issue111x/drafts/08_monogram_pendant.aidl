# Gifts: a monogram pendant, 3 mm walnut. A ring 40 mm across outside, 4 mm wide (32 mm
# inside); the initial "M" in sans Bold 24 mm cap height, centred in the ring, its outline
# joined to the ring where it reaches it; a bail on top: a 10 mm disc whose centre is 2 mm
# above the ring's top, with a 4 mm hole for the chain.

import "std/shapes.aidl"

thickness 3 mm

solid pendant {
    ring = washer(outer=40 mm, inner=32 mm)
    letter = Text("M", (0, 0), size=24, font="sans:Bold", valign="middle")
    CenterInside(letter, ring)

    solid bail {
        disc = Circle(center=(0, 22), diameter=10)
        hole eye {
            c = Circle(center=(0, 22), diameter=4)
        }
        Concentric(eye.c, disc)
    }
    AlignCenterX(bail, ring)
    bail.disc.center.y == ring.ring.top.y + 2 mm
}

assert pendant.ring.bb.width == 40 mm, "ring 40 across"
assert pendant.ring.outer - pendant.ring.inner == 8 mm, "ring 4 mm wide"
assert pendant.letter.size == 24 mm, "M 24 mm tall"
assert pendant.bail.disc.diameter == 10 mm and pendant.bail.eye.c.diameter == 4 mm, "bail 10, hole 4"
assert pendant.bail.disc.center.y - pendant.ring.ring.top.y == 2 mm, "bail 2 above the ring"
assert pendant.letter.bb.width > 32 mm * 0.5, "the M is a bold initial"
