# AIDL standard library: involute spur gears.
#   import "std/gears.aidl"
# Tooth proportions follow the ISO 53 basic rack: addendum 1 m, dedendum
# 1.25 m, pressure angle 20 deg unless given. docs/stdlib.md ("Gears") says how
# the involute is written as circular arcs (within 0.001 mm of the true
# involute) and what is simplified (no root fillet, no undercut).

# An involute spur gear of `teeth` teeth and module `module` (pitch diameter
# module * teeth, outer diameter module * (teeth + 2)), centered at (cx, cy),
# one tooth pointing along `phase` (0 deg: along +x). A `bore` of 0 leaves the
# center solid. `backlash` thins every tooth by that much along the pitch
# circle. Members: `pitch` and `tip` (construction circles of the pitch and
# outer diameters), `hub` (the root disk), `teeth_ring`, `bore_hole`.
def spur_gear(teeth=20, module=2 mm, pressure_angle=20 deg, bore=0 mm,
              backlash=0 mm, phase=0 deg, cx=0 mm, cy=0 mm) -> solid {
    assert teeth >= 3 and teeth == round(teeth), "a gear has a whole number of teeth, at least 3"
    pitch_r = module * teeth / 2
    base_r = pitch_r * cos(pressure_angle)
    tip_r = pitch_r + module
    root_r = pitch_r - 1.25 * module
    # the involute starts on the base circle, or just inside the root circle
    start_r = max(base_r, root_r - 0.1 * module)
    # roll angles (plain radians) of the involute at the start and the tip
    t0 = sqrt(max(0, square(start_r / base_r) - 1))
    t1 = sqrt(square(tip_r / base_r) - 1)
    # half the tooth's angle at the base circle: pi/(2z) + inv(pressure angle)
    half = pi / (2 * teeth) - backlash / (2 * pitch_r) + tan(pressure_angle) - pressure_angle / (1 rad)
    tip_half = half - t1 + atan(t1) / (1 rad)
    start_half = half - t0 + atan(t0) / (1 rad)
    assert tip_half > 0, "the teeth come to a point before the tip circle: use more teeth or a smaller pressure angle"
    assert root_r > bore / 2, "the bore is larger than the root circle"
    # arcs per flank: a 3-point arc's deviation from the involute falls as 1/n^3
    n = max(3, ceil(3.6 * (module / 1 mm) ** (1 / 3)))
    # the upper flank of the tooth on +x as n arcs, each through 3 involute points
    for k in range(n) {
        ps = [base_r * sqrt(1 + square(t)) for t in [t0 + (t1 - t0) * (k + j / 2) / n for j in range(3)]]
        qs = [half - t + atan(t) / (1 rad) for t in [t0 + (t1 - t0) * (k + j / 2) / n for j in range(3)]]
        ax = ps[0] * cos(qs[0])
        ay = ps[0] * sin(qs[0])
        bx = ps[1] * cos(qs[1]) - ax
        by = ps[1] * sin(qs[1]) - ay
        ex = ps[2] * cos(qs[2]) - ax
        ey = ps[2] * sin(qs[2]) - ay
        dd = 2 * (bx * ey - by * ex)
        ux = ax + (ey * (bx * bx + by * by) - by * (ex * ex + ey * ey)) / dd
        uy = ay + (bx * (ex * ex + ey * ey) - ex * (bx * bx + by * by)) / dd
        rad = sqrt(square(ax - ux) + square(ay - uy))
        a_in = atan2(ay - uy, ax - ux)
        a_out = atan2(ay + ey - uy, ax + ex - ux)
        cw = dd < 0
    }
    solid teeth_ring {
        for i in range(teeth) {
            rot = phase + i * 360 deg / teeth
            for k in range(n) {
                # upper flank, and its mirror image about the tooth's axis
                up = Arc(center=(cx + ux[k] * cos(rot) - uy[k] * sin(rot), cy + ux[k] * sin(rot) + uy[k] * cos(rot)),
                         radius=rad[k], start_angle=rot + (a_out[k] if cw[k] else a_in[k]),
                         end_angle=rot + (a_in[k] if cw[k] else a_out[k]))
                lo = Arc(center=(cx + ux[k] * cos(rot) + uy[k] * sin(rot), cy + ux[k] * sin(rot) - uy[k] * cos(rot)),
                         radius=rad[k], start_angle=rot - (a_in[k] if cw[k] else a_out[k]),
                         end_angle=rot - (a_out[k] if cw[k] else a_in[k]))
                Fixed(up.center)
                Fixed(lo.center)
            }
            top = Arc(center=(cx, cy), radius=tip_r, start_angle=rot - tip_half * 1 rad, end_angle=rot + tip_half * 1 rad)
            # close the tooth inside the root disk: two radial lines and a chord
            s_up = (cx + start_r * cos(rot + start_half * 1 rad), cy + start_r * sin(rot + start_half * 1 rad))
            s_lo = (cx + start_r * cos(rot - start_half * 1 rad), cy + start_r * sin(rot - start_half * 1 rad))
            i_up = (cx + root_r / 2 * cos(rot + start_half * 1 rad), cy + root_r / 2 * sin(rot + start_half * 1 rad))
            i_lo = (cx + root_r / 2 * cos(rot - start_half * 1 rad), cy + root_r / 2 * sin(rot - start_half * 1 rad))
            l_up = Line(s_up, i_up)
            chord = Line(i_up, i_lo)
            l_lo = Line(i_lo, s_lo)
            Fixed(top.center)
            Fixed(l_up)
            Fixed(chord)
            Fixed(l_lo)
        }
        axis = Point(cx, cy)
        Fixed(axis)
    }
    hub = Circle(center=(cx, cy), radius=root_r)
    Fixed(hub.center)
    pitch = Circle(center=(cx, cy), radius=pitch_r, construction=true)
    tip = Circle(center=(cx, cy), radius=tip_r, construction=true)
    Concentric(tip, hub)
    Concentric(pitch, hub)
    Coincident(teeth_ring.axis, hub.center)
    if bore > 0 {
        hole bore_hole {
            b = Circle(center=(cx, cy), diameter=bore)
            Fixed(b.center)
        }
        Concentric(bore_hole.b, hub)
    }
}

# Two meshing spur gears of one module: `gear1` (teeth1) centered at (cx, cy)
# with a tooth pointing along `angle`, and `gear2` (teeth2) on that line at the
# center distance module * (teeth1 + teeth2) / 2, turned so that a tooth of
# gear1 sits in a gap of gear2. `center_distance` is readable as a member.
def gear_pair(teeth1=12, teeth2=36, module=2 mm, pressure_angle=20 deg,
              bore1=0 mm, bore2=0 mm, backlash=0 mm, angle=0 deg,
              cx=0 mm, cy=0 mm) -> assembly {
    center_distance = module * (teeth1 + teeth2) / 2
    gear1 = spur_gear(teeth=teeth1, module=module, pressure_angle=pressure_angle,
                      bore=bore1, backlash=backlash, phase=angle, cx=cx, cy=cy)
    gear2 = spur_gear(teeth=teeth2, module=module, pressure_angle=pressure_angle,
                      bore=bore2, backlash=backlash,
                      phase=angle + 180 deg + 180 deg / teeth2,
                      cx=cx + center_distance * cos(angle), cy=cy + center_distance * sin(angle))
    gear2.hub.center == gear1.hub.center + (center_distance * cos(angle), center_distance * sin(angle))
}
