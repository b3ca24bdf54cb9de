# Garden: a flat-pack plant obelisk for a big pot (sweet peas, clematis), cut from 6 mm
# exterior ply. Two identical tapered panels cross-halved into an X: each 500 mm tall, a
# trapezoid 200 mm wide at the ground and 60 mm wide at 460 mm, topped by a 40 mm pointed
# finial. An arch 100 mm wide and 80 mm high (R20 top corners) cut out of the bottom leaves
# two legs to push into the soil. Eight elliptical windows per panel (4 rows, 80 mm apart
# from 130 mm up, one each side of the centre line, shrinking with the taper) for the vines
# to climb through. Halving slots 6.2 mm wide (0.2 clearance): one panel from the tip down
# 210 mm, the other from the arch up 210 mm, meeting over the 420 mm the two share.

units mm
thickness 6 mm
import "std/joints.aidl"

param t = 6 mm, min = 4 mm, max = 9 mm
param base_w = 200 mm, min = 150 mm, max = 260 mm
param top_w = 60 mm, min = 40 mm, max = 90 mm
param body_h = 460 mm, min = 350 mm, max = 560 mm
param tip_h = 40 mm, min = 20 mm, max = 60 mm
param gap_w = 100 mm, min = 60 mm, max = 130 mm
param leg_h = 80 mm, min = 50 mm, max = 120 mm
param rows = 4, min = 2, max = 5
param pitch = 80 mm, min = 60 mm, max = 100 mm
param y0 = 130 mm, min = 110 mm, max = 160 mm
param half = 210 mm, min = 150 mm, max = 260 mm

# the panel's width at height y
def w_at(y) = base_w - (base_w - top_w) * y / body_h

def panel(from_top=true) -> solid {
    body = Trapezoid(center=(0, body_h / 2), bottom_width=base_w, top_width=top_w, height=body_h)
    tip = Triangle(center=(0, body_h + tip_h / 2), base=top_w, height=tip_h)
    hole legs {
        arch = RoundedRectangle(center=(0, (leg_h - 10 mm) / 2), width=gap_w, height=leg_h + 10 mm,
                                corner_radii=[20, 20, 0, 0])
    }
    hole windows {
        for i in range(rows) {
            l = Ellipse(center=(-w_at(y0 + i * pitch) / 4, y0 + i * pitch),
                        rx=w_at(y0 + i * pitch) / 4 - 12 mm, ry=0.16 * w_at(y0 + i * pitch))
            r = Ellipse(center=(w_at(y0 + i * pitch) / 4, y0 + i * pitch),
                        rx=w_at(y0 + i * pitch) / 4 - 12 mm, ry=0.16 * w_at(y0 + i * pitch))
        }
    }
    if from_top {
        x = cross_halving(depth=half, thickness=t, clearance=0.2 mm, cx=0 mm, cy=body_h + tip_h)
    } else {
        x = cross_halving(depth=half, thickness=t, clearance=0.2 mm, rotation=180 deg, cx=0 mm,
                          cy=leg_h)
    }
}

assembly obelisk {
    a = panel(from_top=true)
    b = panel(from_top=false)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    # the request's own numbers
    assert a.body.height + a.tip.bb.height == 500 mm, "500 mm tall"
    assert a.body.bottom_width == 200 mm and a.body.top_width == 60 mm, "200 mm at the ground, 60 at the top"
    assert a.tip.bb.height == 40 mm, "40 mm finial"
    assert a.legs.arch.width == 100 mm and a.legs.arch.bb.top - a.body.bb.bottom == 80 mm, "arch 100 x 80"
    assert len(a.windows.l) + len(a.windows.r) == 8, "8 windows per panel"
    assert a.x.depth == 210 mm and b.x.depth == 210 mm, "halvings 210 mm each"
    assert a.x.depth + b.x.depth == 500 mm - 80 mm, "the halvings meet over the shared 420 mm"
}
