# Request (crafts): a bench stand for my steel ring mandrel, 6 mm ply. The mandrel is 300 mm
# long: a 25 mm handle 80 mm long, then a taper from 22 mm down to 11 mm at the tip. It lies
# level in two U cradles 70 mm above the base (centres): one round the handle 40 mm from its
# end (13 mm radius: 0.5 mm play), one 240 mm from the handle's end where the taper is 14 mm
# (7.5 mm radius). The uprights are trapezoids 70 mm wide at the foot, 46 mm at the top, 75 mm
# above the base, each glued into the base with two 15 mm tenons (0.1 mm clearance). The base
# is 320 x 80 mm with 6 mm corners and four countersunk M4 holes (12 mm in, 8.5 mm heads) to
# screw it to the bench; "RING MANDREL" engraved 6 mm tall along its front strip, between the
# uprights.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 6 mm

param t = 6 mm, min = 3, max = 9
param fit = 0.1 mm, min = 0, max = 0.3

axis_h = 70 mm          # cradle centres above the base's top
top_h = 75 mm           # uprights' top above the base's top
handle_x = -150 mm + 40 mm
taper_x = -150 mm + 240 mm

def upright(r=13 mm) -> solid {
    body = Trapezoid(center=(0, (top_h - t) / 2), bottom_width=70, top_width=46,
                     height=top_h + t)
    tenons = tab_and_slot(part="tab", length=70 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=-t)
    hole cradle {
        c = Circle(center=(0, axis_h), radius=r)
        mouth = Rectangle(corner=(-r, axis_h), opposite=(r, top_h + 1 mm), overrun=true)
    }
}

assembly stand {
    base = mounting_plate(width=320 mm, height=80 mm, corner_radius=6 mm, screw=4, inset=12 mm)
    Countersink(base.corner, diameter=8.5 mm)

    hole mortises {
        at_handle = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=15 mm,
                                 screw=0, clearance=fit, rotation=90 deg, cx=handle_x, cy=0 mm)
        at_taper = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=15 mm,
                                screw=0, clearance=fit, rotation=90 deg, cx=taper_x, cy=0 mm)
    }
    CutInto(mortises, base)

    drawing label {
        name = Text("RING MANDREL", ((handle_x + taper_x) / 2, -33), size=6)
    }
    CutInto(label, base)

    big = upright(r=13 mm)
    small = upright(r=7.5 mm)

    # on the sheet: the uprights above the base
    Above(big, base, gap=10)
    AlignLeft(big, base)
    RightOf(small, big, gap=10)
    AlignBottom(small, big)

    # in 3D: the uprights stand across the base, shoulders on its top face
    Place(base, position=(0, 0, 0))
    Place(big, position=(handle_x + t / 2, 0, t), face="left", up="up")
    Place(small, position=(taper_x + t / 2, 0, t), face="left", up="up")
}

assert abs(stand.base.body.width - 320 mm) < 0.01 mm and abs(stand.base.body.height - 80 mm) < 0.01 mm, "320 x 80 base"
assert abs(stand.big.cradle.c.radius - 13 mm) < 0.01 mm, "13 mm cradle at the handle"
assert abs(stand.small.cradle.c.radius - 7.5 mm) < 0.01 mm, "7.5 mm cradle at the taper"
assert abs((stand.big.cradle.c.center.y - stand.big.body.bb.bottom) - (stand.small.cradle.c.center.y - stand.small.body.bb.bottom)) < 0.01 mm,
    "the mandrel lies level"
assert abs(stand.big.cradle.c.center.y - stand.big.body.bb.bottom - 6 mm - 70 mm) < 0.01 mm, "centres 70 mm above the base"
assert abs(stand.big.body.bb.height - 6 mm - 75 mm) < 0.01 mm, "uprights 75 mm above the base"
assert abs(stand.mortises.at_taper.slot[0].bb.center_x - stand.mortises.at_handle.slot[0].bb.center_x - 200 mm) < 0.01 mm,
    "cradles 40 and 240 mm from the handle's end"
assert distance(stand.label, stand.mortises) >= 10 mm, "label clear of the mortises"
assert stand.big.body.top_width - 2 * 13 mm >= 2 * 8 mm, "8 mm walls beside the big cradle"
