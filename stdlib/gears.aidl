# AIDL standard library: involute spur gears.
#   import "std/gears.aidl"
# Tooth proportions follow the ISO 53 basic rack: addendum 1 m, dedendum
# 1.25 m, pressure angle 20 deg unless given. docs/stdlib.md ("Gears") says how
# the involute is written as tangent circular arcs (within 0.001 mm of the
# true involute) and what is simplified (no root fillet, no undercut).

# An involute spur gear with a center bore. It has `teeth` teeth of module
# `module` (pitch diameter module * teeth, outer diameter module * (teeth + 2)),
# is centered at (cx, cy), one tooth pointing along `phase` (0 deg: along +x).
# A `bore` of 0 leaves the center solid. `backlash` thins every tooth by that
# much along the pitch circle. Members: `pitch` and `tip` (construction
# circles of the pitch and outer diameters), `hub` (the root disk; the gear's
# center is `hub.center`), `teeth_ring`, `bore_hole` (a hole, when the bore is not 0).
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
    # the flank as n biarcs: both ends of each on the involute with the involute's own
    # direction there, so every join is tangent; n grows with the module (deviation ~ m/n^3)
    # and the ends crowd toward the base circle (t ~ k^1.2), where the involute curves most
    n = max(3, ceil(3.8 * (module / 1 mm) ** (1 / 3)))
    # the upper flank of the tooth on +x: the point at roll angle t and its direction
    for k in range(n) {
        ta = t0 + (t1 - t0) * (k / n) ** 1.2
        tb = t0 + (t1 - t0) * ((k + 1) / n) ** 1.2
        pax = base_r * sqrt(1 + ta * ta) * cos(half - ta + atan(ta) / (1 rad))
        pay = base_r * sqrt(1 + ta * ta) * sin(half - ta + atan(ta) / (1 rad))
        pbx = base_r * sqrt(1 + tb * tb) * cos(half - tb + atan(tb) / (1 rad))
        pby = base_r * sqrt(1 + tb * tb) * sin(half - tb + atan(tb) / (1 rad))
        dax = cos(half - ta)
        day = sin(half - ta)
        dbx = cos(half - tb)
        dby = sin(half - tb)
        # the biarc's joint q (equal tangent lengths d)
        vx = pbx - pax
        vy = pby - pay
        vt = vx * (dax + dbx) + vy * (day + dby)
        cc = 1 - (dax * dbx + day * dby)
        d = (sqrt(vt * vt + 2 * cc * (vx * vx + vy * vy)) - vt) / (2 * cc)
        qx = (pax + d * dax + pbx - d * dbx) / 2
        qy = (pay + d * day + pby - d * dby) / 2
        # first arc: from p_a along its direction to q (r1 > 0: turning left)
        r1 = ((qx - pax) * (qx - pax) + (qy - pay) * (qy - pay)) / (2 * (-day * (qx - pax) + dax * (qy - pay)))
        c1x = pax - r1 * day
        c1y = pay + r1 * dax
        s1 = atan2(pay - c1y, pax - c1x) if r1 > 0 else atan2(qy - c1y, qx - c1x)
        e1 = atan2(qy - c1y, qx - c1x) if r1 > 0 else atan2(pay - c1y, pax - c1x)
        # second arc: from p_b backwards (against its direction) to q
        r2 = ((qx - pbx) * (qx - pbx) + (qy - pby) * (qy - pby)) / (2 * (dby * (qx - pbx) - dbx * (qy - pby)))
        c2x = pbx + r2 * dby
        c2y = pby - r2 * dbx
        s2 = atan2(pby - c2y, pbx - c2x) if r2 > 0 else atan2(qy - c2y, qx - c2x)
        e2 = atan2(qy - c2y, qx - c2x) if r2 > 0 else atan2(pby - c2y, pbx - c2x)
    }
    solid teeth_ring {
        # one tooth drawn along `phase`; each of its shapes is patterned round the gear
        # (CircularPattern: every copy exactly the tooth turned by a multiple of 360 deg / teeth)
        cr = cos(phase)
        sr = sin(phase)
        for k in range(n) {
            # the two arcs of the upper flank, and their mirror images about the tooth's axis
            up1 = Arc(center=(cx + c1x[k] * cr - c1y[k] * sr, cy + c1x[k] * sr + c1y[k] * cr),
                      radius=abs(r1[k]), start_angle=phase + s1[k], end_angle=phase + e1[k])
            up2 = Arc(center=(cx + c2x[k] * cr - c2y[k] * sr, cy + c2x[k] * sr + c2y[k] * cr),
                      radius=abs(r2[k]), start_angle=phase + s2[k], end_angle=phase + e2[k])
            lo1 = Arc(center=(cx + c1x[k] * cr + c1y[k] * sr, cy + c1x[k] * sr - c1y[k] * cr),
                      radius=abs(r1[k]), start_angle=phase - e1[k], end_angle=phase - s1[k])
            lo2 = Arc(center=(cx + c2x[k] * cr + c2y[k] * sr, cy + c2x[k] * sr - c2y[k] * cr),
                      radius=abs(r2[k]), start_angle=phase - e2[k], end_angle=phase - s2[k])
            for flank in [up1, up2, lo1, lo2] {
                Fixed(flank.center)
                CircularPattern(flank, teeth, (cx, cy))
            }
        }
        top = Arc(center=(cx, cy), radius=tip_r, start_angle=phase - tip_half * 1 rad, end_angle=phase + tip_half * 1 rad)
        # close the tooth inside the root disk: two radial lines and a chord
        s_up = (cx + start_r * cos(phase + start_half * 1 rad), cy + start_r * sin(phase + start_half * 1 rad))
        s_lo = (cx + start_r * cos(phase - start_half * 1 rad), cy + start_r * sin(phase - start_half * 1 rad))
        i_up = (cx + root_r / 2 * cos(phase + start_half * 1 rad), cy + root_r / 2 * sin(phase + start_half * 1 rad))
        i_lo = (cx + root_r / 2 * cos(phase - start_half * 1 rad), cy + root_r / 2 * sin(phase - start_half * 1 rad))
        l_up = Line(s_up, i_up)
        chord = Line(i_up, i_lo)
        l_lo = Line(i_lo, s_lo)
        Fixed(top.center)
        for line in [l_up, chord, l_lo] {
            Fixed(line)
        }
        for edge in [top, l_up, chord, l_lo] {
            CircularPattern(edge, teeth, (cx, cy))
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

# Two meshing spur gears of one module, as an assembly. `gear1` (teeth1) is
# centered at (cx, cy) with a tooth pointing along `angle`, and `gear2`
# (teeth2) on that line at the center distance module * (teeth1 + teeth2) / 2,
# turned so that a tooth of gear1 sits in a gap of gear2. Members: `gear1`,
# `gear2` (spur_gear instances), `center_distance` (a length).
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
