# Request (holidays): "A small German Christmas pyramid (Weihnachtspyramide), 3 mm birch ply,
# turning on a 4 mm steel rod. Base: two 230 mm discs glued; the top one has four 39.5 mm
# tealight holes on a 160 mm circle at 45, 135, 225 and 315 deg (the lower disc makes them
# pockets), two 15.2 x 3.2 mm slots for the pillars at +-100 mm and an engraved cross at the
# centre where the rod's pivot cup is glued. Two 25 mm pillars, 160 mm between shoulders, a
# 15 x 3 mm tab at each end, carry a 240 x 25 mm bridge (ends fully rounded) with a 5 mm guide
# hole for the rod. A 120 mm carousel disc with a 4 mm hole and six 10.2 x 3.2 mm slots on a
# 45 mm radius (tangential) holds six 70 mm Christmas trees (40 mm wide, three tiers, a 10 x 3
# mm tab under a 12 mm trunk). A 200 mm rotor of 0.5 mm card: a 60 mm hub with eight 30-degree
# blades out to the rim, blades twisted by hand; 4 mm hole. Two 30 mm hub discs with 4 mm holes
# glue under the carousel and the rotor to grip the rod."

thickness 3 mm

base_d = 230 mm
tealight_hole = 39.5 mm
tealight_pcd = 160 mm
pillar_x = 100 mm
pillar_h = 160 mm
carousel_d = 120 mm
tree_r = 45 mm
rotor_d = 200 mm
rod = 4 mm
carousel_z = 60 mm
rotor_z = 185 mm

def disc(d=230 mm, bore=0 mm) -> solid {
    body = Circle(center=(0, 0), diameter=d)
    if bore > 0 mm {
        hole axle { c = Circle(center=(0, 0), diameter=bore) }
    }
}

def pillar() -> solid {
    body = Rectangle(bottom_left=(-12.5, 0), width=25, height=pillar_h)
    foot = Rectangle(center=(0, -1.5), width=15, height=3)
    head = Rectangle(center=(0, pillar_h + 1.5), width=15, height=3)
}

def xmas_tree() -> solid {
    body = Polygon([(0, 70), (10, 52), (5, 52), (15, 34), (8, 34), (20, 14), (6, 14), (6, 0),
                    (5, 0), (5, -3)], mirror="y")
}

assembly pyramid {
    solid base {
        body = Circle(center=(0, 0), diameter=base_d)
        hole tealight {
            c = Circle(center=(tealight_pcd / 2 * cos(45 deg), tealight_pcd / 2 * sin(45 deg)),
                       diameter=tealight_hole)
        }
        tealights = CircularPattern(tealight, 4, body.center)
        hole pillar_slots {
            r1 = Rectangle(center=(pillar_x, 0), width=15.2, height=3.2)
            r2 = Rectangle(center=(-pillar_x, 0), width=15.2, height=3.2)
        }
        drawing pivot_mark {
            h = Line((-5, 0), (5, 0))
            v = Line((0, -5), (0, 5))
        }
        Concentric(pivot_mark.h.midpoint, body)
    }
    base_under = disc(d=base_d)

    pillar_a = pillar()
    pillar_b = pillar()

    solid bridge {
        body = RoundedRectangle(center=(0, 0), width=240, height=25, corner_radius=12.5)
        hole guide { c = Circle(center=(0, 0), diameter=5) }
        hole pillar_slots {
            r1 = Rectangle(center=(pillar_x, 0), width=15.2, height=3.2)
            r2 = Rectangle(center=(-pillar_x, 0), width=15.2, height=3.2)
        }
    }

    solid carousel {
        body = Circle(center=(0, 0), diameter=carousel_d)
        hole axle { c = Circle(center=(0, 0), diameter=rod) }
        hole tree_slot { r = Rectangle(center=(tree_r, 0), width=3.2, height=10.2) }
        tree_slots = CircularPattern(tree_slot, 6, body.center)
    }

    solid rotor {
        thickness 0.5 mm
        hub = Circle(center=(0, 0), diameter=60)
        for i in range(8) {
            blade = Sector(center=(0, 0), radius=rotor_d / 2, inner_radius=20,
                           start_angle=i * 45 deg, end_angle=i * 45 deg + 30 deg)
        }
        hole axle { c = Circle(center=(0, 0), diameter=rod) }
    }

    carousel_hub = disc(d=30 mm, bore=rod)
    rotor_hub = disc(d=30 mm, bore=rod)

    for i in range(6) {
        tree = xmas_tree()
    }

    # ---- flat on the sheet
    RightOf(base_under, base, gap=10)
    AlignCenterY(base_under, base)
    Above(carousel, base, gap=10)
    AlignLeft(carousel, base)
    RightOf(rotor, carousel, gap=10)
    AlignBottom(rotor, carousel)
    RightOf(carousel_hub, rotor, gap=10)
    AlignBottom(carousel_hub, rotor)
    RightOf(rotor_hub, carousel_hub, gap=5)
    AlignBottom(rotor_hub, carousel_hub)
    Below(bridge, base, gap=10)
    AlignLeft(bridge, base)
    RightOf(pillar_a, base_under, gap=10)
    AlignBottom(pillar_a, base_under)
    RightOf(pillar_b, pillar_a, gap=10)
    AlignBottom(pillar_b, pillar_a)
    for i in range(6) {
        Below(tree[i], bridge, gap=10)
        tree[i].bb.left == bridge.bb.left + i * 45 mm
    }

    # ---- assembled: z up, the rod on the z axis
    Place(base_under, position=(0, 0, 0))
    Place(base, position=(0, 0, 3))
    # pillars stand in the x-z plane on the slots at x = +-100, centred on y = 0
    Place(pillar_a, rotation=(90 deg, 0, 0), position=(pillar_x, 1.5, 6))
    Place(pillar_b, rotation=(90 deg, 0, 0), position=(-pillar_x, 1.5, 6))
    Place(bridge, position=(0, 0, 6 + pillar_h))
    Place(carousel_hub, position=(0, 0, carousel_z - 3))
    Place(carousel, position=(0, 0, carousel_z))
    # trees stand tangentially on their slots, tabs down through the carousel
    for i in range(6) {
        Place(tree[i], rotation=(90 deg, 0, i * 60 deg + 90 deg),
              position=((tree_r - 1.5) * cos(i * 60 deg), (tree_r - 1.5) * sin(i * 60 deg),
                        carousel_z + 3))
    }
    Place(rotor_hub, position=(0, 0, rotor_z - 3))
    Place(rotor, position=(0, 0, rotor_z))

    # ---- the request's numbers
    assert base.body.diameter == 230 mm and base_under.body.diameter == 230 mm, "230 discs"
    assert len(base.tealights) == 4, "four tealights"
    assert abs(distance(base.tealights[0].c.center, base.body.center) - 80 mm) < 0.01 mm,
        "on a 160 mm circle"
    assert base.tealights[0].c.diameter == 39.5 mm, "39.5 mm holes"
    assert base.pillar_slots.r1.center.x - base.body.center.x == 100 mm, "pillars at 100"
    assert pillar_a.body.height == 160 mm and pillar_a.body.width == 25 mm, "25 x 160 pillars"
    assert bridge.body.width == 240 mm and bridge.body.height == 25 mm, "240 x 25 bridge"
    assert carousel.body.diameter == 120 mm and len(carousel.tree_slots) == 6, "carousel"
    assert tree[0].bb.height == 73 mm and tree[0].bb.width == 40 mm, "70 mm trees + 3 mm tab"
    assert rotor.bb.width == 200 mm, "200 mm rotor"
    assert len(rotor.blade) == 8, "eight blades"
    # the flames stand outside the carousel, under the blades, clear of the pillars
    assert tealight_pcd / 2 - tealight_hole / 2 > carousel_d / 2, "flames outside the carousel"
    assert tealight_pcd / 2 + tealight_hole / 2 < rotor_d / 2, "flames under the rotor"
    assert rotor_z > 6 + pillar_h + 3 mm + 3 mm, "rotor above the bridge and its hub"
    assert carousel_z + 3 mm + 73 mm < 6 + pillar_h, "trees under the bridge"
}
