# Request: a burger press for 115 mm patties, cut from 6 mm maple ply. A mould ring of three
# glued layers (18 mm deep): a 150 mm disc with two round lifting ears (R15, centred 95 mm out,
# so 220 mm across the ears), a 116 mm cavity, and a 6 mm dowel hole in each ear, 92 mm from
# the centre, to line the layers up. A base plate of the same outline with no cavity, an 8 mm
# hanging hole in one ear and "115 mm" engraved on the other. A 114 mm plunger disc (1 mm
# clearance all round) engraved "PRESS" and a D-shaped handle 100 x 50 mm (R20 top corners,
# a 60 x 22 mm finger slot) glued into the plunger by two 20 mm tenons.

import "std/joints.aidl"

t = 6 mm
thickness t

cavity_d = 116 mm
plunger_d = 114 mm
layers = 3

def press_outline() = Hull(Circle(center=(0, 0), radius=75 mm),
                           Circle(center=(-95 mm, 0), radius=15 mm),
                           Circle(center=(95 mm, 0), radius=15 mm))

def ring_layer() -> solid {
    body = press_outline()
    hole cavity {
        c = Circle(center=(0, 0), diameter=cavity_d)
    }
    hole dowels {
        l = Circle(center=(-92 mm, 0), diameter=6 mm)
        r = Circle(center=(92 mm, 0), diameter=6 mm)
    }
}

def base_plate() -> solid {
    body = press_outline()
    hole hang {
        c = Circle(center=(95 mm, 0), diameter=8 mm)
    }
    drawing mark {
        size_label = Text("115 mm", position=(-95 mm, 0), size=5, valign="middle", rotation=90 deg)
        guide = Circle(center=(0, 0), diameter=cavity_d)
    }
}

def plunger() -> solid {
    disc = Circle(center=(0, 0), diameter=plunger_d)
    m = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                     cx=0 mm, cy=0 mm)
    drawing word {
        w = Text("PRESS", position=(0, -32 mm), size=8, valign="middle")
    }
}

def handle() -> solid {
    body = RoundedRectangle(center=(0, 25 mm), width=100 mm, height=50 mm,
                            corner_radii=[20 mm, 20 mm, 0 mm, 0 mm])
    hole grip {
        s = Slot(center=(0, 30 mm), length=60 mm, width=22 mm)
    }
    # tenons on the bottom edge (y = 0), the handle above it
    ten = tab_and_slot(part="tab", length=100 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                       rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly burger_press {
    base = base_plate()
    Place(base, position=(0, 0, 0), face="up")
    for i in range(layers) {
        ring = ring_layer()
        Place(ring, position=(0, 0, t + i * t), face="up")
    }
    p = plunger()
    # resting on a 12 mm patty
    Place(p, position=(0, 0, t + 12 mm), face="up")
    h = handle()
    Place(h, position=(0, t / 2, t + 12 mm), face="front", up="up")

    # flat layout
    RightOf(ring[0], base, gap=8)
    AlignCenterY(ring[0], base)
    Above(ring[1], base, gap=8)
    AlignLeft(ring[1], base)
    Above(ring[2], ring[0], gap=8)
    AlignLeft(ring[2], ring[0])
    Below(p, base, gap=8)
    AlignLeft(p, base)
    RightOf(h, p, gap=8)
    AlignCenterY(h, p)

    # the request's numbers
    assert len(ring) == 3 and layers * t == 18 mm, "three layers, 18 mm deep"
    assert ring[0].cavity.c.diameter == 116 mm, "116 mm cavity"
    assert p.disc.diameter == 114 mm and (ring[0].cavity.c.diameter - p.disc.diameter) / 2 == 1 mm,
        "114 mm plunger, 1 mm clearance"
    assert ring[0].body.bb.width == 220 mm and ring[0].body.bb.height == 150 mm, "220 across the ears, 150 disc"
    assert distance(ring[0].dowels.l.center, ring[0].cavity.c.center) == 92 mm, "dowels 92 mm out"
    assert h.body.bb.width == 100 mm and h.body.bb.height == 50 mm, "handle 100 x 50"
    assert h.grip.s.length == 60 mm and h.grip.s.width == 22 mm, "finger slot 60 x 22"
    assert distance(h.grip, h.ten) >= 5 mm, "wood between the finger slot and the tenons' shoulder"
}
