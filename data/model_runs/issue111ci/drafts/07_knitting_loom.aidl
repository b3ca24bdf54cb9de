# Request: a 24-peg round knitting loom (for hats), 6 mm birch ply. Two glued rings, 180 mm
# outside and 130 mm inside: the top ring has a blind mortise for each peg (8 x 6 mm, 0.1 mm
# over) on a 77.5 mm radius, every 15 degrees, and an anchor peg sticking 16 mm out of its
# rim halfway between the first two pegs to tie the yarn's tail on; the bottom ring is plain.
# 24 pegs, 12 mm wide (radially) and 6 mm thick, standing 60 mm above the top ring with a
# rounded tip and an 8 mm tenon 6 mm long; each has a 5 mm round groove on its outer edge,
# 14 mm below the tip, so the loops can be lifted over. Pegs laid out in a row beside the
# rings for cutting.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
ring_od = 180 mm
ring_id = 130 mm
pegs = 24
peg_r = 77.5 mm
peg_w = 12 mm
peg_h = 60 mm

def ring(mortised=false) -> solid {
    outer = Circle(center=(0, 0), diameter=ring_od)
    hole bore { c = Circle(center=(0, 0), diameter=ring_id) }
    if mortised {
        anchor = Slot(center=(96 * cos(7.5 deg), 96 * sin(7.5 deg)), length=20, width=8,
                      rotation=7.5 deg)
        for k in range(pegs) {
            m = tab_and_slot(part="slot", length=peg_w, thickness=t, tabs=1, tab=8 mm, screw=0,
                             clearance=0.1 mm, rotation=k * 15 deg,
                             cx=peg_r * cos(k * 15 deg), cy=peg_r * sin(k * 15 deg))
        }
    }
}

def knit_peg() -> solid {
    body = RoundedRectangle(bottom_left=(-peg_w / 2, -t), width=peg_w, height=peg_h + t,
                            corner_radii=[peg_w / 2, peg_w / 2, 0, 0])
    tenon = tab_and_slot(part="tab", length=peg_w, thickness=t, tabs=1, tab=8 mm, screw=0,
                         rotation=180 deg, cx=0, cy=-t)
    hole groove { c = Circle(center=(peg_w / 2, peg_h - 14 mm), diameter=5, overrun=true) }
}

assembly loom {
    top = ring(mortised=true)
    bottom = ring()
    RightOf(bottom, top, gap=10)
    AlignCenterY(bottom, top)
    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, t))

    for k in range(pegs) {
        peg = knit_peg()
        peg.bb.left == -ring_od / 2 + k * (peg_w + 4 mm)
        peg.bb.top == -ring_od / 2 - 10 mm
        Place(peg, position=(peg_r * cos(k * 15 deg) - t / 2 * sin(k * 15 deg),
                             peg_r * sin(k * 15 deg) + t / 2 * cos(k * 15 deg), 2 * t),
              rotation=(90 deg, 0, k * 15 deg))
    }

    assert len(peg) == 24 and len(top.m) == 24, "24 pegs, 24 mortises"
    assert top.outer.diameter == 180 mm and top.bore.c.diameter == 130 mm, "180 / 130 rings"
    assert peg[0].body.bb.top - peg[0].tenon.bb.top == 60 mm, "pegs stand 60 mm above the ring"
    assert distance(top.m[1].slot[0].bb.center, top.outer.center) == 77.5 mm, "pegs on a 77.5 mm radius"
    assert top.anchor.bb.right - top.outer.bb.right >= 15 mm, "anchor peg sticks out 16 mm"
}
