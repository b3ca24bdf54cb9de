# Request (home): "A two-tier flower frog for my glass vase (100 mm mouth), cut from 3 mm clear
# acrylic. A top grid disc 110 mm across rests on the rim: a 14 mm centre hole, six 12 mm holes on
# a 44 mm circle and twelve 10 mm holes on an 84 mm circle. 60 mm below it hangs a lower disc
# 80 mm across (it must pass through the mouth): a 16 mm centre hole and six 14 mm holes on a
# 44 mm circle, so the stems are held at two heights. Three legs 15 mm wide at 120 degrees join
# them: each leg's top tenon (10 mm) sits in a mortise in the top disc, and the lower disc is
# cross-halved onto the legs (slots from its rim meet slots from the legs' inner edges). The legs
# run 5 mm below the lower disc as feet. Press fit: 0.1 mm clearance in every slot."

import "std/joints.aidl"

thickness 3 mm
t = 3 mm            # the acrylic
fit = 0.1 mm        # press-fit clearance
top_d = 110 mm
low_d = 80 mm
spacing = 60 mm     # between the discs (top disc's underside to lower disc's top)
leg_w = 15 mm
foot = 5 mm
leg_r0 = low_d / 2 - leg_w      # the legs' inner edge, from the axis
leg_h = foot + t + spacing + t  # the tenon's tip is flush with the top disc's top
angles = [90 deg, 210 deg, 330 deg]

def leg() -> solid {
    strip = Rectangle(bottom_left=(0, 0), width=leg_w, height=leg_h)
    # the tenon into the top disc's mortise, on the top edge
    tenon = tab_and_slot(part="tab", length=leg_w, thickness=t, tabs=1, tab=10 mm, screw=0,
                         cx=leg_w / 2, cy=leg_h)
    # half-lap from the inner edge (x = 0), at the lower disc's height
    lap = cross_halving(depth=leg_w / 2, thickness=t, clearance=fit, rotation=90 deg,
                        cx=0 mm, cy=foot + t / 2)
}

assembly frog {
    solid top {
        disc = Circle(center=(0, 0), diameter=top_d)
        hole stems {
            mid = Circle(center=(0, 0), diameter=14)
            for i in range(6) {
                inner = Circle(center=(22 * cos(i * 60 deg), 22 * sin(i * 60 deg)), diameter=12)
            }
            for i in range(12) {
                outer = Circle(center=(42 * cos(15 deg + i * 30 deg), 42 * sin(15 deg + i * 30 deg)),
                               diameter=10)
            }
        }
        for i in range(3) {
            mortise = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=1, tab=10 mm,
                                   screw=0, clearance=fit, rotation=angles[i],
                                   cx=(leg_r0 + leg_w / 2) * cos(angles[i]),
                                   cy=(leg_r0 + leg_w / 2) * sin(angles[i]))
        }
    }

    solid lower {
        disc = Circle(center=(0, 0), diameter=low_d)
        hole stems {
            mid = Circle(center=(0, 0), diameter=16)
            for i in range(6) {
                ring = Circle(center=(22 * cos(i * 60 deg), 22 * sin(i * 60 deg)), diameter=14)
            }
        }
        for i in range(3) {
            lap = cross_halving(depth=leg_w / 2, thickness=t, clearance=fit,
                                rotation=angles[i] - 90 deg,
                                cx=(low_d / 2) * cos(angles[i]), cy=(low_d / 2) * sin(angles[i]))
        }
    }

    for i in range(3) {
        legs = leg()
    }

    # lay the flat parts apart on the sheet
    RightOf(lower, top, gap=5)
    AlignCenterY(lower, top)
    RightOf(legs[0], lower, gap=5)
    RightOf(legs[1], legs[0], gap=5)
    RightOf(legs[2], legs[1], gap=5)
    AlignBottom(legs[0], lower)
    AlignBottom(legs[1], lower)
    AlignBottom(legs[2], lower)

    # 3D: lower disc at z 0..3, top disc 60 above it; each leg stands radially, its +x outward
    Place(lower, position=(0, 0, 0))
    Place(top, position=(0, 0, t + spacing))
    for i in range(3) {
        Place(legs[i], position=(leg_r0 * cos(angles[i]) - t / 2 * sin(angles[i]),
                                 leg_r0 * sin(angles[i]) + t / 2 * cos(angles[i]), -foot),
              face=(sin(angles[i]), -cos(angles[i]), 0), up="up")
    }

    # the request's numbers
    assert top.disc.diameter == 110 mm, "top disc 110 mm"
    assert lower.disc.diameter == 80 mm, "lower disc 80 mm"
    assert lower.disc.diameter < 100 mm, "the lower disc passes the 100 mm mouth"
    assert top.disc.diameter > 100 mm, "the top disc rests on the rim"
    assert len(top.stems.inner) == 6 and len(top.stems.outer) == 12, "6 + 12 holes on top"
    assert len(lower.stems.ring) == 6, "six holes below"
    assert top.stems.mid.diameter == 14 mm and lower.stems.mid.diameter == 16 mm, "centre holes"
    assert top.stems.inner[0].diameter == 12 mm and top.stems.outer[0].diameter == 10 mm, "top holes"
    assert lower.stems.ring[0].diameter == 14 mm, "lower holes"
    assert distance(top.stems.inner[0].center, top.disc.center) == 22 mm, "44 mm circle"
    assert distance(top.stems.outer[0].center, top.disc.center) == 42 mm, "84 mm circle"
    assert distance(lower.stems.ring[0].center, lower.disc.center) == 22 mm, "44 mm circle below"
    assert len(legs) == 3, "three legs"
    assert legs[0].strip.width == 15 mm, "legs 15 mm wide"
    assert leg_h - foot - 2 * t == 60 mm, "discs 60 mm apart"
    # the holes keep clear of the mortises and the rim
    assert distance(top.stems, top.mortise[0]) >= 3 mm, "web between a stem hole and a mortise"
    assert top.disc.diameter / 2 - (42 mm + 5 mm) >= 5 mm, "rim outside the outer holes"
}
