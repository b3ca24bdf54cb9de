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
# much along the pitch circle. `addendum` is the tip's height over the pitch
# circle in modules (1: ISO 53; `ring_gear` cuts its spaces 1.25 deep). `mate`,
# the teeth of the gear it meshes (0: not given), cuts the tips back to where
# the line of action meets the mate's base circle, so that they never run into
# a small mate's flank below it (involute interference; `gear_pair`,
# `gear_train` and `planetary` give it). Members: `pitch` and `tip` (construction
# circles of the pitch and outer diameters), `hub` (the root disk; the gear's
# center is `hub.center`), `teeth_ring`, `bore_hole` (a hole, when the bore is not 0).
# Anchor: (cx, cy) is the centre of `hub`.
def spur_gear(teeth=20, module=2 mm, pressure_angle=20 deg, bore=0 mm,
              backlash=0 mm, phase=0 deg, cx=0 mm, cy=0 mm, addendum=1, mate=0) -> solid {
    assert teeth >= 3 and teeth == round(teeth), "a gear has a whole number of teeth, at least 3"
    assert module > 0 mm, "the module (the pitch diameter / teeth) is more than 0, e.g. 2 mm"
    assert addendum > 0, "the addendum (the tip's height over the pitch circle, in modules) is more than 0, e.g. 1"
    pitch_r = module * teeth / 2
    base_r = pitch_r * cos(pressure_angle)
    assert mate >= 0 and mate == round(mate), "the mate is a whole number of teeth, or 0 (not given)"
    # the tips end where the line of action touches the mate's base circle (where its
    # involute starts): sqrt(rb^2 + (a sin(pressure angle))^2) from the centre, a the
    # centre distance; a mate of 17 teeth or more never needs it (short of a rack)
    mate_r = sqrt(square(base_r) + square(module * (teeth + mate) / 2 * sin(pressure_angle)))
    tip_r = pitch_r + addendum * module if mate == 0 else min(pitch_r + addendum * module, mate_r)
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
    # tip_half > 0 at the ISO tip circle (addendum 1), written over the arguments alone (half -
    # t1 + atan(t1) > 0), so that a form's backlash slider ends where the teeth would come to a
    # point; then the same at the tip circle drawn (another addendum, a mate's cut)
    assert backlash < module * teeth * (pi / (2 * teeth) + tan(pressure_angle) - pressure_angle / (1 rad) - sqrt(square((teeth + 2) / (teeth * cos(pressure_angle))) - 1) + atan(sqrt(square((teeth + 2) / (teeth * cos(pressure_angle))) - 1)) / (1 rad)), "the teeth come to a point before the tip circle: use more teeth, a smaller pressure angle or less backlash"
    assert tip_half > 0, "the teeth come to a point before the tip circle: a smaller addendum, more teeth or less backlash"
    assert root_r > bore / 2, "the bore is larger than the root circle"
    # a bore leaves a wall of 0.55 mm or more inside the root circle (module * (teeth - 2.5)
    # across; the forms' axles, W0507's 0.5 mm)
    assert bore <= max(0 mm, module * (teeth - 2.5) - 1.1 mm), "the bore leaves a wall thinner than 0.55 mm inside the root circle: bore <= module * (teeth - 2.5) - 1.1 mm (or more teeth, a larger module)"
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

# An internal (ring) gear: `teeth` teeth of `module` pointing inward from an
# annular plate, centered at (cx, cy). Its tooth spaces are an external
# spur_gear's teeth (the same involute, `backlash` widening every space along
# the pitch circle) 1.25 modules deep (ISO 53's dedendum: a pinion's tips
# clear the roots by 0.25 module; less where the spaces would come to a point).
# Its teeth are cut back to the addendum circle module * (teeth - 2) / 2, or
# further out when the `pinion` (the teeth of the smallest gear meshing inside
# it; 0: not given) would meet them below its base circle. The plate reaches
# `rim` past the roots (outer diameter module * (teeth + 2.5) + 2 rim). At
# `phase` 0 deg a tooth space points along +x. A pinion of z teeth meshes inside
# it at the centre distance module * (teeth - z) / 2 (`planetary` builds a set).
# Members: `body` (the plate's circle), `cut` (the hole: `cut.teeth`, the
# spur_gear of the spaces, and `cut.tips`, the addendum circle), `pitch` (a
# construction circle of the pitch diameter module * teeth).
# Anchor: (cx, cy) is the centre of `body`.
def ring_gear(teeth=48, module=2 mm, pressure_angle=20 deg, rim=6 mm, backlash=0.05 mm,
              phase=0 deg, cx=0 mm, cy=0 mm, pinion=0) -> solid {
    assert teeth >= 10 and teeth == round(teeth), "a ring gear has a whole number of teeth, at least 10"
    assert module > 0 mm, "the module (the pitch diameter / teeth) is more than 0, e.g. 2 mm"
    assert rim > 0 mm, "the rim past the tooth roots is more than 0"
    assert backlash >= 0 mm, "the backlash is 0 or more (it widens the spaces)"
    assert pinion >= 0 and pinion < teeth and pinion == round(pinion), "the pinion is a whole number of teeth, fewer than the ring's, or 0 (not given)"
    rr = module * teeth / 2
    z = teeth
    # the tips: where the line of action touches the pinion's base circle (its involute's
    # start) lies sqrt(rb^2 + (a sin(pressure angle))^2) from the centre, rb the ring's base
    # radius and a the centre distance; tips inside that would run into the pinion's flank
    # below its base circle (involute interference), so they end there
    clear_r = sqrt(square(rr * cos(pressure_angle)) + square(module * (teeth - pinion) / 2 * sin(pressure_angle)))
    tip_r = rr - module if pinion == 0 else max(rr - module, clear_r)
    # the spaces 1.25 modules deep, or as deep (in steps of 0.05 module) as they go before
    # they come to a point (few teeth at a large pressure angle: at 30 deg, under 38 teeth)
    sp = pi / (2 * teeth) + backlash / (module * teeth) + tan(pressure_angle) - pressure_angle / (1 rad)
    depth = max([1] + [d for d in [1.05, 1.1, 1.15, 1.2, 1.25] if sp - sqrt(square((teeth + 2 * d) / (teeth * cos(pressure_angle))) - 1) + atan(sqrt(square((teeth + 2 * d) / (teeth * cos(pressure_angle))) - 1)) / (1 rad) > 0.002])
    body = Circle(center=(cx, cy), radius=rr + 1.25 * module + rim)
    Fixed(body.center)
    pitch = Circle(center=(cx, cy), radius=rr, construction=true)
    Concentric(pitch, body)
    hole cut {
        teeth = spur_gear(teeth=z, module=module, pressure_angle=pressure_angle,
                          backlash=-backlash, phase=phase, cx=cx, cy=cy, addendum=depth)
        tips = Circle(center=(cx, cy), radius=tip_r)
        Fixed(tips.center)
        teeth.hub.center == tips.center
    }
    cut.tips.center == (cx, cy)
}

# Two meshing spur gears of one module, as an assembly. `gear1` (teeth1) is
# centered at (cx, cy) with a tooth pointing along `angle`, and `gear2`
# (teeth2) on that line at the center distance module * (teeth1 + teeth2) / 2,
# turned so that a tooth of gear1 sits in a gap of gear2. Members: `gear1`,
# `gear2` (spur_gear instances), `center_distance` (a length).
# Anchor: (cx, cy) is the centre of `gear1.hub`.
def gear_pair(teeth1=12, teeth2=36, module=2 mm, pressure_angle=20 deg,
              bore1=0 mm, bore2=0 mm, backlash=0 mm, angle=0 deg,
              cx=0 mm, cy=0 mm) -> assembly {
    center_distance = module * (teeth1 + teeth2) / 2
    gear1 = spur_gear(teeth=teeth1, module=module, pressure_angle=pressure_angle,
                      bore=bore1, backlash=backlash, phase=angle, cx=cx, cy=cy, mate=teeth2)
    gear2 = spur_gear(teeth=teeth2, module=module, pressure_angle=pressure_angle,
                      bore=bore2, backlash=backlash, mate=teeth1,
                      phase=angle + 180 deg + 180 deg / teeth2,
                      cx=cx + center_distance * cos(angle), cy=cy + center_distance * sin(angle))
    gear2.hub.center == gear1.hub.center + (center_distance * cos(angle), center_distance * sin(angle))
}

# Spur gears meshing in a row on a plate with axle holes.
# `teeth` lists the gears' tooth counts from left to right (2 to 8 gears, each
# meshing the next), all of `module`; the axles lie on one line at the centre
# distances module * (z1 + z2) / 2, in a plate 5 mm larger than the gears'
# tips, each gear bored for its axle (`axle` diameter). Flat, the plate is at
# (cx, cy) and the gears in mesh above it; assembled, the plate lies on z = 0
# and each gear on it on its axle (the plate's holes are axle_hole[i]);
# `lift` raises the gears that much more above the plate (a demonstrator's
# gears 10 mm up on their axles: lift=10 mm). Members: `plate`, `gear[i]`
# (spur_gear instances), `x` (the axles' x offsets from the first).
# Anchor: (cx, cy) is the centre of `plate`.
def gear_train(teeth=[12, 36, 12, 30], module=2 mm, axle=4 mm, backlash=0.05 mm,
               thickness=3 mm, lift=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    assert lift >= 0 mm, "lift is a height above the plate: 0 or more"
    margin = 5 mm
    gap = 5 mm
    n = len(teeth)
    assert n >= 2 and n <= 8, "a gear train has 2 to 8 gears"
    z = teeth + [0, 0, 0, 0, 0, 0, 0, 0]
    # s[k]: the teeth of gears 0..k; the axle of gear k is module * (2 s[k] - z0 - zk) / 2
    s = [z[0], z[0] + z[1], z[0] + z[1] + z[2], z[0] + z[1] + z[2] + z[3],
         z[0] + z[1] + z[2] + z[3] + z[4], z[0] + z[1] + z[2] + z[3] + z[4] + z[5],
         z[0] + z[1] + z[2] + z[3] + z[4] + z[5] + z[6],
         z[0] + z[1] + z[2] + z[3] + z[4] + z[5] + z[6] + z[7]]
    x = [module * (2 * s[k] - z[0] - z[k]) / 2 for k in range(n)]
    tip = max([module * (z[k] + 2) / 2 for k in range(n)])
    span = x[n - 1] + module * (z[0] + z[n - 1] + 4) / 2 + 2 * margin
    left = cx - span / 2 + margin + module * (z[0] + 2) / 2
    deep = 2 * (tip + margin)
    above = cy + deep / 2 + gap + tip
    solid plate {
        body = Rectangle(center=(cx, cy), width=span, height=deep)
        Fixed(body.center)
        for k in range(n) {
            hole axle_hole {
                c = Circle(center=(left + x[k], cy), diameter=axle)
                Fixed(c.center)
            }
            axle_hole.c.center == (left + x[k], cy)
        }
    }
    for k in range(n) {
        # a tooth of gear k-1 points at gear k, so gear k turns a gap to it: half a pitch
        # more for each even count among gears 1..k
        half = len([1 for j in range(1, k + 1) if z[j] % 2 == 0]) % 2
        # its tips cut back for the smaller of its neighbours (`spur_gear`'s mate)
        mate = min([z[j] for j in [k - 1, k + 1] if j >= 0 and j < n])
        gear = spur_gear(teeth=z[k], module=module, bore=axle, backlash=backlash, mate=mate,
                         phase=half * 180 deg / z[k], cx=left + x[k], cy=above)
        gear.hub.center == (left + x[k], above)
        Place(gear, position=(-cx, -above, thickness + lift))
    }
    Place(plate, position=(-cx, -cy, 0 mm))
}

# A rack and a pinion in mesh, on a base plate.
# The rack has `rack_teeth` straight teeth of `module` (pitch pi * module,
# flanks at the pressure angle 20 deg, addendum 1 module, or r sin^2(20 deg)
# for a pinion of radius r under 18 teeth, dedendum 1.25 module) on a bar
# `height` below the roots; the pinion (`teeth`, bored for `axle`) has its
# centre module * teeth / 2 above the rack's pitch line, a gap over the rack's
# middle tooth (of an even count: the one right of the middle). `backlash`
# thins the rack's teeth and the pinion's. Flat, the base plate is at (cx, cy)
# and the rack and pinion in mesh above it; assembled, both lie on the plate
# (`lift` higher: a gap under them, for spacers). Members: `rack`, `pinion`
# (a spur_gear), `base`, `pitch` (the rack's pitch).
# Anchor: (cx, cy) is the centre of `base`.
def rack_and_pinion(teeth=16, module=2 mm, rack_teeth=12, height=8 mm, axle=4 mm,
                    backlash=0.05 mm, thickness=3 mm, lift=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    gap = 5 mm
    assert lift >= 0 mm, "lift is a height above the base: 0 or more"
    assert rack_teeth >= 2 and rack_teeth == round(rack_teeth), "a rack has a whole number of teeth, at least 2"
    pitch = pi * module
    length = rack_teeth * pitch
    r = module * teeth / 2
    # the flat view: the base plate at (cx, cy), the rack's pitch line `line` above it
    base_h = height + 2.25 * module + r + module + 2 * gap
    line = cy + base_h / 2 + gap + height + 1.25 * module
    solid rack {
        bar = Rectangle(center=(cx, line - 1.25 * module - height / 2), width=length, height=height)
        Fixed(bar.center)
        # one tooth over each pitch: a trapezoid from the root line to the tip line (and a
        # foot down into the bar),
        # pitch / 2 - backlash wide at the pitch line, its flanks at 20 deg
        ta = tan(20 deg)
        w = (pitch / 2 - backlash) / 2
        # the tips end where the line of action touches the pinion's base circle, r sin^2(20
        # deg) over the pitch line (under 18 teeth: less than a module), so that they never
        # run into the pinion's flank below it (involute interference)
        ha = min(module, r * square(sin(20 deg)))
        for i in range(rack_teeth) {
            xc = cx + (i - (rack_teeth - 1) / 2) * pitch
            wr = w + 1.25 * module * ta
            tooth = Polygon([(xc - wr, line - 1.25 * module - height / 2),
                             (xc + wr, line - 1.25 * module - height / 2),
                             (xc + wr, line - 1.25 * module),
                             (xc + w - ha * ta, line + ha),
                             (xc - w + ha * ta, line + ha),
                             (xc - wr, line - 1.25 * module)])
            Fixed(tooth.points[0])
        }
    }
    # the pinion over the rack's middle tooth (an odd count) or the tooth half a pitch right of
    # the middle gap (even), a gap turned down onto it: its teeth straddle that tooth (a tooth
    # turned down into a gap runs the rack's tips into the flanks of a pinion of few teeth)
    px = cx + (0 mm if rack_teeth % 2 == 1 else pitch / 2)
    down = -90 deg + 180 deg / teeth
    pinion = spur_gear(teeth=teeth, module=module, bore=axle, backlash=backlash, phase=down,
                       cx=px, cy=line + r)
    pinion.hub.center == (px, line + r)
    solid base {
        body = Rectangle(center=(cx, cy), width=length, height=base_h)
        Fixed(body.center)
        hole axle_hole {
            c = Circle(center=(px, cy - base_h / 2 + gap + height + 1.25 * module + r), diameter=axle)
            Fixed(c.center)
        }
        axle_hole.c.center == (px, cy - base_h / 2 + gap + height + 1.25 * module + r)
    }
    # assembled: the base on z = 0, the rack and the pinion on it, the rack's bar along its
    # lower edge less `gap`
    shift = cy - base_h / 2 + gap + height + 1.25 * module - line
    Place(base, position=(-cx, -cy, 0 mm))
    Place(rack, position=(-cx, shift - cy, thickness + lift))
    Place(pinion, position=(-cx, shift - cy, thickness + lift))
}

# A planetary gear set: sun, planets and ring gear, on a carrier.
# All of `module`: the `sun` gear at (cx, cy), `planets` gears of `planet`
# teeth evenly round it at the centre distance module * (sun + planet) / 2, and
# a ring of `ring` internal teeth (an annular plate `rim` wider than the tooth
# spaces). It assembles only if ring = sun + 2 planet and (ring + sun) divides
# by planets (an assertion says which rule fails and the count to use). The
# carrier, a disc with the sun's and the planets' axle holes (`axle`), is laid
# beside the set flat and under it assembled (`lift` lower: a gap between
# the carrier and the set). The ring's cut-out is its hole
# cut (cut.teeth, a spur_gear with the backlash negative, and cut.tips).
# Members: `sun_gear`, `planet_gear[i]` (spur_gear instances), `ring_gear`,
# `carrier`, `center_distance`.
# Anchor: (cx, cy) is the centre of `sun_gear.hub`.
def planetary(sun=12, planet=18, ring=48, planets=3, module=2 mm, axle=4 mm,
              backlash=0.05 mm, rim=6 mm, thickness=3 mm, lift=0 mm, cx=0 mm,
              cy=0 mm) -> assembly {
    gap = 5 mm
    assert lift >= 0 mm, "lift is the gap between the carrier and the set: 0 or more"
    assert planets >= 2 and planets == round(planets), "a planetary set has at least 2 planets"
    # the ring rule: the right side is the ring count to use
    assert ring == sun + 2 * planet, "ring = sun + 2 * planet: give ring the right side's count"
    # the spacing rule: the right side is the nearest sun count that satisfies it (then
    # ring = that + 2 * planet)
    fits = [sun + d for d in range(-planets, planets + 1) if sun + d >= 3 and (2 * (sun + d) + 2 * planet) % planets == 0]
    near = min([abs(f - sun) for f in fits])
    sun_ok = [f for f in fits if abs(f - sun) == near][0]
    assert sun == sun_ok, "(ring + sun) must divide by planets for the planets to sit evenly: use the right side's sun count and ring = sun + 2 * planet"
    # neighbouring planets, (sun + planet) x module x sin(180 deg / planets) apart, clear
    # each other's tips (planet + 2 modules across)
    assert (sun + planet) * sin(180 deg / planets) > planet + 2, "the planets run into each other: fewer planets, a larger sun or smaller planets ((sun + planet) x sin(180 deg / planets) > planet + 2)"
    center_distance = module * (sun + planet) / 2
    rr = module * ring / 2
    sun_gear = spur_gear(teeth=sun, module=module, bore=axle, backlash=backlash, cx=cx, cy=cy, mate=planet)
    sun_gear.hub.center == (cx, cy)
    for k in range(planets) {
        a = k * 360 deg / planets
        # the sun's tooth offset seen from planet k, in pitches: -k sun / planets; the planet
        # puts a gap there
        planet_gear = spur_gear(teeth=planet, module=module, bore=axle, backlash=backlash, mate=sun,
                                phase=a + 180 deg + (k * sun / planets - 0.5) * 360 deg / planet,
                                cx=cx + center_distance * cos(a), cy=cy + center_distance * sin(a))
        planet_gear.hub.center == (cx + center_distance * cos(a), cy + center_distance * sin(a))
    }
    # the ring (`ring_gear`, above): a space where planet 0's tooth points out
    ring_gear = ring_gear(teeth=ring, module=module, rim=rim, backlash=backlash,
                          phase=(planet - 1) / 2 * 360 deg / ring, cx=cx, cy=cy, pinion=planet)
    ring_gear.body.center == (cx, cy)
    # the carrier: flat, beside the ring; assembled, under the set
    ox = cx + 2 * (rr + 1.25 * module + rim) + gap
    solid carrier {
        body = Circle(center=(ox, cy), radius=rr + module)
        Fixed(body.center)
        hole centre_hole {
            c = Circle(center=(ox, cy), diameter=axle)
            Fixed(c.center)
        }
        centre_hole.c.center == (ox, cy)
        for k in range(planets) {
            hole axle_hole {
                c = Circle(center=(ox + center_distance * cos(k * 360 deg / planets),
                                   cy + center_distance * sin(k * 360 deg / planets)), diameter=axle)
                Fixed(c.center)
            }
            axle_hole.c.center == (ox + center_distance * cos(k * 360 deg / planets),
                                   cy + center_distance * sin(k * 360 deg / planets))
        }
    }
    Place(carrier, position=(cx - ox, 0 mm, -thickness - lift))
}
