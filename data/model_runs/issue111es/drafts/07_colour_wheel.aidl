# Request: "An artist's colour-mixing wheel for my painting class, in 3 mm birch ply (the
# students paint the segments). Two discs on a 5 mm Chicago screw through their centres.
# The base disc is 220 mm across, with a ring of twelve 30-degree hue segments from radius
# 50 to 92 mm engraved as outlines (two circles and twelve spokes), Yellow at the top and
# going clockwise Yellow-Orange, Orange, Red-Orange, Red, Red-Violet, Violet, Blue-Violet,
# Blue, Blue-Green, Green, Yellow-Green; each name engraved (3.5 mm capitals) along the rim
# outside its segment, readable (the lower ones not upside down). The top disc is 140 mm
# across with a pointer reaching out to radius 88 mm at the top to pick the key colour,
# KEY engraved under it, and five windows (radius 54 to 66 mm, 20 degrees wide) cut through
# it: the complement opposite the key, the split complements 30 degrees either side of it
# and the triad 120 degrees either side of the key; each window labelled just inside it
# (COMPLEMENT, SPLIT, TRIAD, 3.5 mm). Kerf 0.15 mm."

units mm
thickness 3 mm
kerf 0.15 mm

base_r = 110 mm
ring_in = 50 mm
ring_out = 92 mm
top_r = 70 mm
pointer_r = 88 mm
win_in = 54 mm
win_out = 66 mm
win_span = 20 deg
pivot_d = 5 mm
names = ["YELLOW", "YELLOW-ORANGE", "ORANGE", "RED-ORANGE", "RED", "RED-VIOLET", "VIOLET",
         "BLUE-VIOLET", "BLUE", "BLUE-GREEN", "GREEN", "YELLOW-GREEN"]
# hue i's segment is centred at 90 deg - i * 30 deg (clockwise from the top)
def hue_angle(i) = 90 deg - i * 30 deg
# the windows, by their angle from the key (the top); labels
win_angles = [90 deg + 120 deg, 90 deg + 150 deg, 270 deg, 90 deg - 150 deg + 360 deg, 90 deg - 120 deg + 360 deg]
win_names = ["TRIAD", "SPLIT", "COMPLEMENT", "SPLIT", "TRIAD"]

assembly colour_wheel {
    solid base {
        disc = Circle(center=(0, 0), radius=base_r)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        drawing segments {
            inner = Circle(center=(0, 0), radius=ring_in)
            outer = Circle(center=(0, 0), radius=ring_out)
            for i in range(12) {
                spoke = Line(polar((0, 0), ring_in, hue_angle(i) + 15 deg),
                             polar((0, 0), ring_out, hue_angle(i) + 15 deg))
            }
        }
        drawing labels {
            upper = Circle(center=(0, 0), radius=ring_out + 3 mm, construction=true)
            lower = Circle(center=(0, 0), radius=ring_out + 3 mm + 3.5 mm, construction=true)
            for i in range(12) {
                # upper half reads clockwise over the top; lower half flipped to read upright
                name = Text(names[i], along=upper if sin(hue_angle(i)) >= 0 else lower,
                            angle=hue_angle(i), size=3.5, flip=sin(hue_angle(i)) < 0)
            }
        }
    }

    solid top {
        disc = Hull(Circle(center=(0, 0), radius=top_r), Point(0, pointer_r))
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        for k in range(5) {
            hole win {
                w = Sector(center=(0, 0), radius=win_out, inner_radius=win_in,
                           start_angle=win_angles[k] - win_span / 2, end_angle=win_angles[k] + win_span / 2)
            }
        }
        drawing marks {
            key_ring = Circle(center=(0, 0), radius=win_out - 6 mm, construction=true)
            key = Text("KEY", along=key_ring, angle=90 deg, size=5)
            label_ring = Circle(center=(0, 0), radius=win_in - 2 mm, construction=true)
            for k in range(5) {
                lab = Text(win_names[k], along=label_ring, angle=win_angles[k], size=3.5, flip=true)
            }
        }
    }

    RightOf(top, base, gap=10 mm)
    AlignCenterY(top.pivot, base.pivot)
    # in 3D: the top disc on the base, on one pivot
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 3 mm))

    # the request's numbers
    assert base.disc.diameter == 220 mm and top.disc.bb.width == 140 mm, "discs 220 and 140"
    assert top.disc.bb.top - top.pivot.c.center.y == 88 mm, "pointer to radius 88"
    assert len(names) == 12 and len(segments_count) == 12, "twelve hues"
    assert len(top.win) == 5, "five windows"
    assert names[0] == "YELLOW" and names[4] == "RED" and names[8] == "BLUE", "primaries a third apart"
    assert win_angles[2] - 90 deg == 180 deg, "complement opposite the key"
    assert abs(win_angles[1] - win_angles[2]) == 30 deg and abs(win_angles[3] - win_angles[2]) == 30 deg,
        "split complements 30 deg either side"
    assert win_angles[0] - 90 deg == 120 deg and 90 deg + 360 deg - win_angles[4] == 120 deg,
        "triad 120 deg either side of the key"
    assert top.pivot.c.diameter == 5 mm and base.pivot.c.diameter == 5 mm, "5 mm pivot"
    assert win_out < top_r and win_in > ring_in and win_out < ring_out, "windows over the hue ring"
}
segments_count = [0 for i in range(12)]
