# Request: a swivel-lid salt box for the stove side, glued up from 6 mm plywood layers.
# 110 mm across; a round salt well 80 mm across (15 mm walls); 5 layers = 30 mm tall:
# a solid base disc, three rings, and a lid disc that swings open sideways on a 6 mm dowel
# near the rim. The dowel is pressed into the top ring (5.8 mm hole) and turns freely in
# the lid (6.3 mm hole), 47.5 mm from the centre (in the middle of the wall). Opposite the
# dowel the lid has a round thumb tab sticking out 8 mm past the rim to push it open.
# "SALT" engraved filled on the lid in a serif font, 16 mm tall.

import "std/shapes.aidl"

thickness 6 mm

t = 6 mm
dia = 110 mm
well = 80 mm
pin_r = 47.5 mm      # dowel's distance from the centre
tab_out = 8 mm       # thumb tab past the rim

assembly salt_box {
    solid base {
        disc = Circle(center=(0, 0), diameter=dia)
    }
    Place(base, position=(0, 0, 0), face="up")

    for i in range(3) {
        solid ring {
            layer = washer(outer=dia, inner=well)
            if i == 2 {
                # the top ring holds the dowel tight
                hole pin_seat { c = Circle(center=(pin_r, 0), diameter=5.8 mm) }
            }
        }
        ring.bb.center == (125 * (i + 1), 0)
        Place(ring, position=(0, 0, t * (i + 1)), face="up")
    }

    solid lid {
        disc = Circle(center=(0, 0), diameter=dia)
        thumb = Circle(center=(-(dia / 2 + tab_out - 9 mm), 0), radius=9 mm)
        outline = Hull(disc, thumb)
        hole pivot { c = Circle(center=(pin_r, 0), diameter=6.3 mm) }
        drawing word {
            t = Text("SALT", position=(0, 0), size=16, font="serif", valign="middle", fill=true)
        }
    }
    lid.disc.center == (500, 0)
    Place(lid, position=(0, 0, 4 * t), face="up")

    assert base.disc.diameter == 110 mm, "110 mm across"
    assert ring[0].layer.ring.diameter - ring[0].layer.bore.b.diameter == 2 * 15 mm,
        "15 mm walls"
    assert len(ring) == 3, "three rings"
    assert (1 + len(ring) + 1) * t == 30 mm, "30 mm tall"
    assert lid.pivot.c.center.x - lid.disc.center.x == 47.5 mm, "dowel 47.5 mm from the centre"
    assert lid.disc.bb.left - lid.thumb.bb.left == 8 mm, "thumb tab 8 mm past the rim"
}
