# Request (pets): a holder for my rabbit's 500 ml water bottle (70 mm across, neck 30 mm)
# on the outside of the hutch's mesh door, the spout through the mesh. 3 mm ply.
# A back plate 100 wide x 180 tall, R8 corners, tied to the mesh with cable ties through
# three pairs of 10 x 4 slots (one above the other, 12 apart) 85 mm up, at the middle and
# 35 mm either side. Two ring plates stand out from it, glued in with two 20 mm tenons each:
# the top one 150 mm up with a 72 mm hole round the bottle, the bottom one 40 mm up with a
# 36 mm hole that stops the bottle's shoulder; both holes centred 50 mm out from the back
# plate's face, the ring plates 100 wide at the back and 10 mm of wood round the 72 mm hole.
# Under each ring plate two 40 x 40 triangular gussets, 40 mm either side of the middle,
# each with a 15 mm tenon into the ring plate and one into the back plate. The rabbit's name,
# BISCUIT, engraved filled (sans bold, 12 mm caps) across the back plate above the top ring.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
plate_w = 100 mm
plate_h = 180 mm
out = 50 mm          # bottle axis from the back plate's face
z_lo = 40 mm         # ring plates' undersides above the bottom of the back plate
z_hi = 150 mm
g_x = 40 mm          # gussets either side of the middle
g_leg = 40 mm
ring_r = 72 mm / 2 + 10 mm

def ring(bore=72 mm) -> solid {
    # drawn from above: y toward the back plate; the tenon tips at y = t (the back plate's
    # back face), the back plate's front face at y = 0
    body = Hull(Rectangle(bottom_left=(-plate_w / 2, -20), width=plate_w, height=20 + t),
                Circle(center=(0, -out), radius=ring_r))
    tenons = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=2, tab=20 mm,
                          screw=0, cx=0 mm, cy=t)
    hole bore_hole { c = Circle(center=(0, -out), diameter=bore) }
    for s in [-1, 1] {
        m = tab_and_slot(part="slot", length=g_leg, thickness=t, tabs=1, tab=15 mm, screw=0,
                         rotation=90 deg, cx=s * g_x, cy=-g_leg / 2)
    }
}

def gusset() -> solid {
    # drawn from the side: x toward the back plate (its front face at x = 0), y up (the ring
    # plate's underside at y = 0); tenons up into the ring plate and back into the back plate
    web = Polygon([(0, 0), (-g_leg, 0), (0, -g_leg)])
    top_strip = Rectangle(bottom_left=(-g_leg, 0), width=g_leg, height=t)
    back_strip = Rectangle(bottom_left=(0, -g_leg), width=t, height=g_leg)
    top_tab = tab_and_slot(part="tab", length=g_leg, thickness=t, tabs=1, tab=15 mm, screw=0,
                           cx=-g_leg / 2, cy=t)
    back_tab = tab_and_slot(part="tab", length=g_leg, thickness=t, tabs=1, tab=15 mm, screw=0,
                            rotation=-90 deg, cx=t, cy=-g_leg / 2)
}

assembly bottle_holder {
    solid back {
        plate = RoundedRectangle(center=(0, plate_h / 2), width=plate_w, height=plate_h,
                                 corner_radius=8)
        lo = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                          cx=0 mm, cy=z_lo + t / 2)
        hi = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                          cx=0 mm, cy=z_hi + t / 2)
        for s in [-1, 1] {
            glo = tab_and_slot(part="slot", length=g_leg, thickness=t, tabs=1, tab=15 mm,
                               screw=0, rotation=90 deg, cx=s * g_x, cy=z_lo - g_leg / 2)
            ghi = tab_and_slot(part="slot", length=g_leg, thickness=t, tabs=1, tab=15 mm,
                               screw=0, rotation=90 deg, cx=s * g_x, cy=z_hi - g_leg / 2)
        }
        hole ties {
            for x in [-35, 0, 35] {
                for dz in [-6, 6] {
                    s = Slot(center=(x, 85 + dz), length=10, width=4)
                }
            }
        }
        drawing name {
            t1 = Text("BISCUIT", position=(0, (z_hi + t + plate_h) / 2), size=12,
                      font="sans:Bold", valign="middle", fill=true, max_width=84 mm)
        }
    }
    ring_lo = ring(bore=36 mm)
    ring_hi = ring(bore=72 mm)
    for i in range(4) {
        g = gusset()
    }

    # assembled: the back plate's front face at y = 0, the bottle in front of it (-y)
    Place(back, position=(0, t, 0), face="front", up="up")
    Place(ring_lo, position=(0, 0, z_lo), face="up", up="back")
    Place(ring_hi, position=(0, 0, z_hi), face="up", up="back")
    gx = [-g_x, g_x, -g_x, g_x]
    gz = [z_lo, z_lo, z_hi, z_hi]
    for i in range(4) {
        Place(g[i], position=(gx[i] - t / 2, 0, gz[i]), face="right", up="up")
    }

    # laid out flat
    RightOf(ring_lo, back, gap=6)
    AlignTop(ring_lo, back)
    Below(ring_hi, ring_lo, gap=6)
    AlignLeft(ring_hi, ring_lo)
    RightOf(g[0], ring_lo, gap=6)
    AlignTop(g[0], ring_lo)
    RightOf(g[1], g[0], gap=6)
    AlignTop(g[1], g[0])
    Below(g[2], g[0], gap=6)
    AlignLeft(g[2], g[0])
    RightOf(g[3], g[2], gap=6)
    AlignTop(g[3], g[2])

    # the request's numbers
    assert back.plate.bb.width == 100 mm and back.plate.bb.height == 180 mm, "back 100 x 180"
    assert ring_hi.bore_hole.c.diameter == 72 mm and ring_lo.bore_hole.c.diameter == 36 mm, "holes"
    assert back.lo.slot[0].bb.center_y - back.plate.bb.bottom == 40 mm + t / 2, "bottom ring 40 up"
    assert back.hi.slot[0].bb.center_y - back.plate.bb.bottom == 150 mm + t / 2, "top ring 150 up"
    assert ring_hi.bb.top - t - ring_hi.bore_hole.c.center.y == 50 mm, "bottle 50 out"
    assert ring_hi.body.bb.width == 100 mm, "ring plates 100 wide at the back"
    assert distance(back.name, back.hi) >= 3 mm, "name clear of the top ring's mortises"
    assert distance(back.name, back.plate.top) >= 3 mm, "name inside the plate"
    assert sum([len(r) for r in back.ties.s]) == 6, "three pairs of tie slots"
}
