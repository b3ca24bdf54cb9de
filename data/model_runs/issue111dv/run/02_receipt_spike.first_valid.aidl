# Request (office): a desk receipt spike (note spindle), 6 mm ply, glued.
# - Blade: stands 150 mm above the base, 24 mm wide at the base tapering to a blunt
#   R3 tip; a 6 mm tenon under it goes through the base's top disc.
# - Foot: a cross piece 70 mm long at the base, 30 mm tall, tapering to 30 mm wide at
#   its top, cross-halved with the blade (each cut half of the 36 mm overlap), its own
#   6 mm tenon into the base.
# - Base: two 90 mm discs glued together, the top one with the plus-shaped mortise;
#   "PAID" engraved along the rim at the back, "FILED" along the rim at the front
#   (5 mm letters, readable from outside).

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm
param height = 150 mm, min = 100 mm, max = 200 mm

blade_w = 24 mm
foot_len = 70 mm
foot_h = 30 mm
foot_top = 30 mm
base_d = 90 mm
overlap = foot_h + t                  # the halved height: tenon + foot

assembly receipt_spike {
    solid blade {
        # y = 0: the base's top face; the tenon below it
        shank = Hull(Rectangle(center=(0, -t / 2), width=blade_w, height=t),
                     Circle(center=(0, height - 3 mm), radius=3 mm))
        halving = cross_halving(depth=overlap / 2, thickness=t, rotation=180 deg, cx=0, cy=-t)
    }

    solid foot {
        body = Polygon([(-foot_len / 2, -t), (foot_len / 2, -t), (foot_len / 2, 0),
                        (foot_top / 2, foot_h), (-foot_top / 2, foot_h), (-foot_len / 2, 0)])
        halving = cross_halving(depth=overlap / 2, thickness=t, cx=0, cy=foot_h)
    }

    solid top_disc {
        disc = Circle(center=(0, 0), diameter=base_d)
        hole mortise {
            for_blade = Rectangle(center=(0, 0), width=t, height=blade_w)
            for_foot = Rectangle(center=(0, 0), width=foot_len, height=t)
        }
        drawing words {
            rim = Circle(center=(0, 0), radius=base_d / 2 - 6 mm, construction=true)
            back_word = Text("PAID", along=rim, size=5, valign="middle")
            front_word = Text("FILED", along=rim, size=5, valign="middle", flip=true)
        }
        Fixed(disc)
    }

    solid bottom_disc {
        disc = Circle(center=(0, 0), diameter=base_d)
    }

    # on the sheet
    RightOf(bottom_disc, top_disc, gap=8)
    AlignTop(bottom_disc, top_disc)
    RightOf(blade, bottom_disc, gap=8)
    AlignTop(blade, bottom_disc)
    Below(foot, top_disc, gap=8)
    AlignLeft(foot, top_disc)

    # in 3D: the base on the table, blade along y, foot along x
    Place(bottom_disc, position=(0, 0, 0), face="up")
    Place(top_disc, position=(0, 0, t), face="up")
    Place(blade, position=(-t / 2, 0, 2 * t), face="right", up="up")
    Place(foot, position=(0, t / 2, 2 * t), face="front", up="up")

    # the request's numbers
    assert blade.shank.bb.top - (blade.shank.bb.bottom + t) == 150 mm, "blade 150 mm above the base"
    assert blade.shank.bb.width == 24 mm, "24 mm at the base"
    assert foot.body.bb.width == 70 mm and foot.body.bb.height - t == 30 mm, "foot 70 x 30"
    assert blade.halving.depth + foot.halving.depth == 36 mm, "halvings fill the overlap"
    assert top_disc.disc.diameter == 90 mm and bottom_disc.disc.diameter == 90 mm, "90 mm base"
    assert top_disc.mortise.for_foot.width == foot.body.bb.width, "foot tenon fits"
}
