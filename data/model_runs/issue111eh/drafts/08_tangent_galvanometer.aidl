# Request (science): a tangent galvanometer for the school lab, 3 mm plywood.
# Coil former: three glued ring layers standing upright, the coil's centre 100 mm above the
# base's top. Core layer: outer R80, inner R68; the two cheeks: outer R84, inner R68, so the
# wire winds in a 3 mm wide, 4 mm deep groove all round. Each layer has a foot 120 mm wide
# from the base up into the ring (8 mm into the core's band); the core's foot goes through
# the base on two 20 mm tenons (0.1 mm clearance), and a 4 mm arc slot through the core's
# foot carries the groove past the foot. The compass shelf, 56 (across) x 120 mm (front to
# back), passes through the ring with its top 5 mm under the coil's centre, on two uprights
# 56 wide at 50 mm in front of and behind the coil, each on one 20 mm tenon top and bottom.
# On the shelf a 76 x 76 collar (R4) with a 45.6 mm hole holds a 45 mm button compass; round
# the hole a deflection scale engraved: ticks every 10 deg (3 mm, 5 mm every 30 deg) from
# 24 mm out, numbers 0-90-0 every 30 deg (3 mm) on a 31 mm circle, 0 along the coil's plane.
# Base 220 x 160 mm, R6: two 4.2 mm holes for binding posts at x = +-90, 62 mm in front of
# the coil; "TANGENT GALVANOMETER" engraved filled, 7 mm sans bold, centred 68 mm in front.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
c = 100 mm          # the coil's centre above the base's top
shelf_top = c - 5 mm

def defl(a) = min(a % 180, 180 - a % 180)

# a ring layer, drawn with y = 0 on the base's top, x across
# FIX after the first valid program: W0504 was right: a groove all round the core cuts the
# core's foot off its ring. Now the core is a plain ring (R68-R80) and its foot is a
# separate spacer below the groove (cut back to R84), glued between the cheeks' feet and
# carrying the tenons; the cheeks keep their own feet.
def ring_layer(outer=80 mm, feet=true) -> solid {
    ring = Circle(center=(0, c), radius=outer)
    if feet {
        foot = Rectangle(corner=(-60, 0), opposite=(60, c - 80 mm + 8 mm))
    }
    hole bore {
        b = Circle(center=(0, c), radius=68)
    }
}

# the core's foot: between the cheeks' feet under the groove, on two tenons through the base
def spacer() -> solid {
    foot = Rectangle(corner=(-60, -t), opposite=(60, c - 80 mm + 8 mm))
    hole groove {
        g = Circle(center=(0, c), radius=84)
    }
    tenons = tab_and_slot(part="tab", length=120 mm, thickness=t, tabs=2, tab=20 mm,
                          screw=0, rotation=180 deg, cx=0, cy=-t)
}

# an upright under the shelf: y = 0 on the base's top, tenons into the base and the shelf
def upright() -> solid {
    body = Rectangle(corner=(-28, -t), opposite=(28, shelf_top))
    low = tab_and_slot(part="tab", length=56 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                       rotation=180 deg, cx=0, cy=-t)
    high = tab_and_slot(part="tab", length=56 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                        rotation=0 deg, cx=0, cy=shelf_top)
}

assembly galvanometer {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=220, height=160, corner_radius=6)
        ring_slots = tab_and_slot(part="slot", length=120 mm, thickness=t, tabs=2, tab=20 mm,
                                  screw=0, clearance=0.1 mm, cx=0, cy=0)
        front_slot = tab_and_slot(part="slot", length=56 mm, thickness=t, tabs=1, tab=20 mm,
                                  screw=0, clearance=0.1 mm, cx=0, cy=-50)
        back_slot = tab_and_slot(part="slot", length=56 mm, thickness=t, tabs=1, tab=20 mm,
                                 screw=0, clearance=0.1 mm, cx=0, cy=50)
        hole posts {
            l = Circle(center=(-90, -62), diameter=4.2)
            r = Circle(center=(90, -62), diameter=4.2)
        }
        drawing title {
            n = Text("TANGENT GALVANOMETER", position=(0, -68), size=7, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    core = ring_layer(outer=80 mm, feet=false)
    foot = spacer()
    cheek_f = ring_layer(outer=84 mm)
    cheek_b = ring_layer(outer=84 mm)
    up_f = upright()
    up_b = upright()
    solid shelf {
        plate = Rectangle(center=(0, 0), width=56, height=120)
        m_f = tab_and_slot(part="slot", length=56 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                           clearance=0.1 mm, cx=0, cy=-50)
        m_b = tab_and_slot(part="slot", length=56 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                           clearance=0.1 mm, cx=0, cy=50)
    }
    solid collar {
        plate = RoundedRectangle(center=(0, 0), width=76, height=76, corner_radius=4)
        hole seat {
            s = Circle(center=(0, 0), diameter=45.6)
        }
        drawing scale {
            for a in range(0, 360, 10) {
                tick = Line((24 * cos(a * 1 deg), 24 * sin(a * 1 deg)),
                            ((24 + (5 if a % 30 == 0 else 3)) * cos(a * 1 deg),
                             (24 + (5 if a % 30 == 0 else 3)) * sin(a * 1 deg)))
            }
            ring = Circle(center=(0, 0), radius=31, construction=true)
            for a in range(0, 360, 30) {
                num = Text(str(defl(a)), along=ring, angle=a * 1 deg, size=3)
            }
        }
    }

    # laid out flat
    RightOf(core, base, gap=5)
    AlignBottom(core, base)
    Below(foot, core, gap=5)
    AlignCenterX(foot, core)
    RightOf(cheek_f, core, gap=5)
    AlignBottom(cheek_f, base)
    RightOf(cheek_b, cheek_f, gap=5)
    AlignBottom(cheek_b, base)
    Below(up_f, base, gap=5)
    AlignLeft(up_f, base)
    RightOf(up_b, up_f, gap=5)
    AlignTop(up_b, up_f)
    RightOf(shelf, up_b, gap=5)
    AlignTop(shelf, up_f)
    RightOf(collar, shelf, gap=5)
    AlignTop(collar, up_f)

    # assembled: x across, y front to back, z up from the base's top
    Place(base, position=(0, 0, -t), face="up", up="back")
    Place(core, position=(0, t / 2, 0), face="front", up="up")
    Place(foot, position=(0, t / 2, 0), face="front", up="up")
    Place(cheek_f, position=(0, -t / 2, 0), face="front", up="up")
    Place(cheek_b, position=(0, t / 2, 0), face="back", up="up")
    Place(up_f, position=(0, -50 mm + t / 2, 0), face="front", up="up")
    Place(up_b, position=(0, 50 mm - t / 2, 0), face="back", up="up")
    Place(shelf, position=(0, 0, shelf_top - t), face="up", up="back")
    Place(collar, position=(0, 0, shelf_top), face="up", up="back")

    # the request's numbers
    assert core.ring.center.y - (foot.foot.bb.bottom + 3 mm) == 100 mm, "coil centre 100 up"
    assert cheek_f.ring.center.y - cheek_f.foot.bb.bottom == 100 mm, "cheeks stand on the base"
    assert core.ring.radius == 80 mm and cheek_f.ring.radius == 84 mm, "groove 4 deep"
    assert core.bore.b.radius == 68 mm, "inner R68"
    assert base.plate.bb.width == 220 mm and base.plate.bb.height == 160 mm, "base 220 x 160"
    assert shelf.plate.bb.width == 56 mm and shelf.plate.bb.height == 120 mm, "shelf 56 x 120"
    assert up_f.body.bb.top - (up_f.body.bb.bottom + 3 mm) == 100 mm - 5 mm, "shelf top 5 under"
    # the shelf and the collar pass through the ring's opening
    assert sqrt(28 ** 2 + 8 ** 2) <= 68 - 3, "shelf clear of the bore"
    assert sqrt(38 ** 2 + 8 ** 2) <= 68 - 3, "collar clear of the bore"
    assert collar.seat.s.diameter == 45.6 mm, "compass seat 45.6"
    assert distance(collar.scale, collar.seat) >= 1 mm, "scale clear of the seat"
    assert collar.scale.bb.width <= 76 mm - 2 mm, "numbers on the collar"
    assert distance(base.title, base.posts) >= 3 mm, "title clear of the binding posts"
    assert distance(base.title, base.front_slot) >= 3 mm, "title clear of the mortise"
    assert len(collar.scale.num) == 12 and len(collar.scale.tick) == 36, "12 numbers, 36 ticks"
}
