# Request: a hanging herb-drying ring for the kitchen ceiling, 4 mm birch ply. The ring is
# 280 mm across with a 35 mm wide band (inside diameter 210 mm). My laser bed is only
# 300 x 200 mm, so the ring is cut as two half rings joined where they meet by a flat sliding
# dovetail across the band at each side (one tail, 10 mm deep, 0.1 mm clearance), the tails on
# the lower half. Round the outer edge 12 hook notches, evenly 30 deg apart starting at 15 deg
# (so none lands on a joint): a 4 mm slot in from the edge ending in an 8 mm round seat centred
# 125 mm from the middle, for the twine loops of the bunches. Three 5 mm holes for the hanging
# cords at 30, 150 and 270 deg, 115 mm from the middle. "THYME - SAGE - ROSEMARY" engraved
# along the top of the band, 7 mm letters. Each half must fit the 300 x 200 bed.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 4 mm

outer_r = 140 mm
inner_r = 105 mm
mid_r = (outer_r + inner_r) / 2
band_w = outer_r - inner_r
dt_depth = 10 mm
seat_r = 125 mm
cord_r = 115 mm

def cord_hole(a) -> hole {
    c = Circle(center=(cord_r * cos(a), cord_r * sin(a)), diameter=5 mm)
}

assembly herb_ring {
    solid upper {
        band = Sector(center=(0, 0), radius=outer_r, inner_radius=inner_r,
                      start_angle=0 deg, end_angle=180 deg)
        hole notch {
            s = Slot(start=(145 mm * cos(15 deg), 145 mm * sin(15 deg)),
                     end=(seat_r * cos(15 deg), seat_r * sin(15 deg)), width=4 mm)
            seat = Circle(center=(seat_r * cos(15 deg), seat_r * sin(15 deg)), diameter=8 mm)
        }
        notches = CircularPattern(notch, 6, band.center, step=30 deg)
        cord_a = cord_hole(a=30 deg)
        cord_b = cord_hole(a=150 deg)
        socket_r = dovetail(part="socket", length=band_w, depth=dt_depth, tails=1,
                            clearance=0.1 mm, cx=mid_r, cy=0 mm)
        socket_l = dovetail(part="socket", length=band_w, depth=dt_depth, tails=1,
                            clearance=0.1 mm, cx=-mid_r, cy=0 mm)
        label = text_on_arc(text="THYME - SAGE - ROSEMARY", radius=109 mm, size=7 mm,
                            angle=90 deg)
    }

    solid lower {
        half = Sector(center=(0, 0), radius=outer_r, inner_radius=inner_r,
                      start_angle=170 deg, end_angle=370 deg, construction=true)
        keep = Rectangle(corner=(-150, -150), opposite=(150, dt_depth), construction=true)
        band = Intersect(half, keep)
        hole notch {
            s = Slot(start=(145 mm * cos(195 deg), 145 mm * sin(195 deg)),
                     end=(seat_r * cos(195 deg), seat_r * sin(195 deg)), width=4 mm)
            seat = Circle(center=(seat_r * cos(195 deg), seat_r * sin(195 deg)), diameter=8 mm)
        }
        notches = CircularPattern(notch, 6, (0, 0), step=30 deg)
        cord_c = cord_hole(a=270 deg)
        tail_r = dovetail(part="tail", length=band_w, depth=dt_depth, tails=1, cx=mid_r, cy=0 mm)
        tail_l = dovetail(part="tail", length=band_w, depth=dt_depth, tails=1, cx=-mid_r, cy=0 mm)
    }

    # the request's numbers
    assert upper.band.radius * 2 == 280 mm, "ring 280 mm across"
    assert upper.band.radius - upper.band.inner_radius == 35 mm, "35 mm band"
    assert len(upper.notches) + len(lower.notches) == 12, "12 hook notches"
    assert upper.bb.width <= 300 mm and upper.bb.height <= 200 mm, "upper half fits the bed"
    assert lower.bb.width <= 300 mm and lower.bb.height <= 200 mm, "lower half fits the bed"
    assert lower.bb.top - upper.bb.bottom == 10 mm, "tails 10 mm deep"
}
