# Request (science): a filtration stand for two 75 mm glass funnels over 250 ml conical
# flasks, from 4 mm ply. A 240 x 120 base and a 240 x 100 shelf (corners rounded r6),
# joined by two 100 mm deep uprights standing 192 mm apart (outside faces), each with two
# 20 mm tenons top and bottom through mortises, glued. The shelf's top is 160 mm above
# the bench. The shelf has two 50 mm holes for the funnels, 110 mm apart, centred in its
# depth, "A" and "B" engraved in front of them and "FILTRATION" between them near the
# front edge (6 mm single-stroke letters). The base has an 85 mm circle engraved under
# each hole to set the flask on. Each upright has a 100 x 40 mm slot window.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
param height = 160 mm, min = 120 mm, max = 250 mm    # shelf top above the bench
param pitch = 110 mm, min = 90 mm, max = 160 mm      # between the funnels
param funnel_hole = 50 mm, min = 30 mm, max = 70 mm
depth = 100 mm
# FIX after the first valid program: W0505 showed the 85 mm flask circles (x 12.5..97.5)
# crossing the uprights' mortises (x 94..98): the flasks would not fit between uprights
# 192 mm apart at a 110 mm pitch. The pitch is the request's; the uprights move out.
outer = 212 mm          # the uprights' outside faces
up_x = outer / 2 - t / 2   # the uprights' mid-planes
tab = 20 mm

def upright() -> solid {
    body = Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=height)
    top = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=tab, screw=0,
                       cx=0 mm, cy=height)
    bottom = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=tab, screw=0,
                          rotation=180 deg, cx=0 mm, cy=0 mm)
    hole window { s = Slot(center=(0, height / 2), length=100, width=40, rotation=90 deg) }
}

assembly stand {
    solid base {
        body = Rectangle(center=(0, 0), width=240, height=120)
        Fillet(body, 6)
        left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=tab, screw=0,
                            rotation=90 deg, cx=-up_x, cy=0 mm)
        right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=tab, screw=0,
                             rotation=90 deg, cx=up_x, cy=0 mm)
        drawing spots {
            a = Circle(center=(-pitch / 2, 0), diameter=85)
            b = Circle(center=(pitch / 2, 0), diameter=85)
        }
    }
    solid shelf {
        body = Rectangle(center=(0, 0), width=240, height=100)
        Fillet(body, 6)
        left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=tab, screw=0,
                            rotation=90 deg, cx=-up_x, cy=0 mm)
        right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=tab, screw=0,
                             rotation=90 deg, cx=up_x, cy=0 mm)
        hole funnels {
            a = Circle(center=(-pitch / 2, 0), diameter=funnel_hole)
            b = Circle(center=(pitch / 2, 0), diameter=funnel_hole)
        }
        drawing labels {
            la = Text("A", position=(-pitch / 2, -40), size=6, valign="middle")
            lb = Text("B", position=(pitch / 2, -40), size=6, valign="middle")
            title = Text("FILTRATION", position=(0, -40), size=6, valign="middle")
        }
    }
    left_up = upright()
    right_up = upright()

    # flat on the sheet
    Above(shelf, base, gap=8)
    AlignLeft(shelf, base)
    RightOf(left_up, base, gap=8)
    AlignBottom(left_up, base)
    RightOf(right_up, left_up, gap=8)
    AlignBottom(right_up, base)

    # assembled: X across, Y front to back, Z up; the base on the bench
    Place(base, position=(0, 0, 0))
    Place(shelf, position=(0, 0, height - t))
    Place(left_up, position=(-outer / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_up, position=(outer / 2 - t, 0, 0), rotation=(90 deg, 0, 90 deg))

    assert base.body.bb.width == 240 mm and base.body.bb.height == 120 mm, "240 x 120 base"
    assert shelf.body.bb.width == 240 mm and shelf.body.bb.height == 100 mm, "240 x 100 shelf"
    assert left_up.body.bb.height == 160 mm, "shelf top 160 above the bench"
    assert shelf.funnels.b.center.x - shelf.funnels.a.center.x == 110 mm, "funnels 110 apart"
    assert shelf.funnels.a.diameter == 50 mm, "50 mm funnel holes"
    assert base.spots.a.diameter == 85 mm, "85 mm flask circles"
    assert base.spots.b.right.x <= outer / 2 - t - 3 mm, "the flasks clear the uprights by 3 mm"
    assert shelf.funnels.a.center.x - shelf.funnels.a.radius - (-up_x + t / 2) >= 10 mm, "hole clear of the upright"
}
