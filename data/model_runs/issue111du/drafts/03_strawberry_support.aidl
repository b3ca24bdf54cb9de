# Request (garden): a strawberry support that holds a plant's fruit trusses off the soil, cut
# from 6 mm exterior ply. A flat ring 300 mm across with a 220 mm opening, on three legs.
# Each leg is 320 mm long overall: a 30 mm wide tenon 6 mm long at the top (flush with the
# ring's top), shoulders 7 mm each side (the leg is 44 mm wide) that the ring rests on, and a
# 50 mm point at the bottom to push into the soil. The three mortises, 30 x 6 mm and running
# along the ring, sit on the middle of the band (radius 130) at 30, 150 and 270 deg.
# STRAWBERRIES engraved (bold, filled, 8 mm) along the top of the band between two legs.
# Pushed 70 mm into the soil, the ring's top stands 250 mm above it.

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 9 mm
ring_od = 300 mm
ring_id = 220 mm
mid_r = 130 mm
leg_len = 320 mm
leg_w = 44 mm
tenon_w = 30 mm
point_len = 50 mm
sink = 70 mm

def leg() -> solid {
    # the tenon's top at y = 0, the leg hanging below it
    p = Polygon([(-tenon_w / 2, 0), (tenon_w / 2, 0), (tenon_w / 2, -t), (leg_w / 2, -t),
                 (leg_w / 2, -(leg_len - point_len)), (0, -leg_len),
                 (-leg_w / 2, -(leg_len - point_len)), (-leg_w / 2, -t), (-tenon_w / 2, -t)])
    Fillet([p.points[3], p.points[7]], 3)
}

assembly strawberry_support {
    solid ring {
        disc = Circle(center=(0, 0), diameter=ring_od)
        hole opening { c = Circle(center=(0, 0), diameter=ring_id) }
        hole mortise { r = Rectangle(center=(mid_r * cos(30 deg), mid_r * sin(30 deg)),
                                     width=tenon_w, height=t, rotation=-60 deg) }
        mortises = CircularPattern(mortise, 3, (0, 0))
        drawing label {
            path = Circle(center=(0, 0), radius=mid_r, construction=true)
            word = Text("STRAWBERRIES", along=path, size=8, valign="middle", font="sans:Bold",
                        fill=true)
        }
    }

    for i in range(3) {
        legs = leg()
        # flat: the legs stand in a row right of the ring
        legs.bb.left == ring.bb.right + 10 mm + i * (leg_w + 10 mm)
        AlignTop(legs, ring)
        # assembled: each leg's face looks out along its radius, its width along the ring
        Place(legs, position=((mid_r - t / 2) * cos(30 deg + i * 120 deg),
                              (mid_r - t / 2) * sin(30 deg + i * 120 deg), leg_len - sink),
              face=(cos(30 deg + i * 120 deg), sin(30 deg + i * 120 deg), 0), up="up")
    }
    Place(ring, position=(0, 0, leg_len - sink - t))

    assert ring.disc.diameter == 300 mm and ring.opening.c.diameter == 220 mm, "ring 300 / 220"
    assert len(legs) == 3 and len(ring.mortises) == 3, "three legs, three mortises"
    assert legs[0].bb.height == 320 mm, "legs 320 mm long"
    assert legs[0].bb.width == 44 mm, "legs 44 mm wide"
    assert legs[0].bb.height - 70 mm == 250 mm, "ring top 250 mm above the soil"
    assert (ring_od - ring_id) / 2 - t >= 2 * 15 mm, "the band is wide enough round a mortise"
}
