# Request (kitchen): a lazy susan for the spice cupboard, 6 mm birch ply, on a 6 inch
# (150 mm square, 8 mm tall) steel turntable bearing. Three parts:
# - base disc 250 mm across; four 2.5 mm pilot holes for the bearing's lower plate at the
#   corners of a 135 mm square (centred); one 10 mm access hole 55 mm from the centre through
#   which the top is screwed on;
# - top disc 300 mm across; four 2.5 mm pilot holes for the bearing's upper plate on a 110 mm
#   circle (so each comes round over the access hole), "HERBS & SPICES" engraved in bold
#   outline letters 14 mm tall round the top, following a 120 mm radius;
# - gallery ring glued on the top's rim so jars can't slide off: 300 mm outside, 12 mm wide.
# Show it assembled: base on the table, bearing 8 mm, top, ring on top.

thickness 6 mm

import "std/shapes.aidl"

BASE_D = 250 mm
TOP_D = 300 mm
BEARING_H = 8 mm
ACCESS_R = 55 mm
RIM_W = 12 mm

assembly lazy_susan {
    solid base {
        disc = Circle(center=(0, 0), diameter=BASE_D)
        square = Rectangle(center=(0, 0), width=135, height=135, construction=true)
        hole pilot { c = Circle(center=(-67.5, -67.5), diameter=2.5) }
        pilots = CornerPattern(pilot, square)
        hole access { c = Circle(center=(ACCESS_R, 0), diameter=10) }
    }

    solid top {
        disc = Circle(center=(0, 0), diameter=TOP_D)
        screws = bolt_circle(count=4, pcd=2 * ACCESS_R, hole_d=2.5 mm, start=0 deg)
        Concentric(screws.pitch, disc)
        drawing label {
            path = Circle(center=(0, 0), radius=120, construction=true)
            words = Text("HERBS & SPICES", along=path, size=14, font="sans:Bold")
        }
        Concentric(label.path, disc)
    }

    gallery = washer(outer=TOP_D, inner=TOP_D - 2 * RIM_W)

    # flat on the sheet, side by side
    RightOf(top, base, gap=10)
    AlignCenterY(top, base)
    RightOf(gallery, top, gap=10)
    AlignCenterY(gallery, top)

    # assembled: the base on the table, the bearing between, the top and its ring above
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 6 + BEARING_H))
    Place(gallery, position=(0, 0, 6 + BEARING_H + 6))

    assert base.disc.diameter == 250 mm, "base 250"
    assert top.disc.diameter == 300 mm, "top 300"
    assert gallery.ring.diameter - gallery.bore.b.diameter == 2 * 12 mm, "rim 12 mm wide"
    assert len(base.pilots) == 4 and len(top.screws.bolt) == 4, "four screws each plate"
    assert base.access.c.center.x - base.disc.center.x == 55 mm, "access hole 55 from centre"
    assert top.screws.pitch.diameter == 110 mm, "upper plate screws on a 110 circle"
    assert top.label.words.size == 14 mm, "letters 14 mm"
    # the letters stay clear of the gallery ring (inside its bore)
    assert top.label.words.bb.top - top.disc.center.y < (TOP_D / 2 - RIM_W), "text clear of the ring"
}
