# Request: a holder that hangs a 250 ml small-animal water bottle (body 62 mm across, cap
# 30 mm) inside a glass hamster tank, hooked over the tank's 5 mm glass wall, cut from 4 mm
# ply. Two side cheeks stand square to the glass: 100 mm deep and 150 mm tall at the front,
# sloping back to a hook that rides on the glass: a 7 mm gap (5 mm glass + clearance) with
# an outer leg 25 mm long and a 12 mm thick bridge over the glass top, 200 mm above the
# cheeks' bottom. Between the cheeks (82 mm apart inside) two rings 100 mm deep hold the
# bottle: the upper one (its middle 130 mm up) with a 64 mm hole, the lower one (30 mm up)
# with a 34 mm hole for the cap, both holes 50 mm out from the glass, centred across. Each
# ring is glued by two 20 mm tabs per side into mortises in the cheeks. A paw print cut
# through each cheek between the rings, and the hamster's name "PEANUT" engraved 7 mm
# tall on the upper ring in front of the hole.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
depth = 100 mm       # cheeks and rings, out from the glass
inside = 82 mm       # between the cheeks
glass = 5 mm
gap = 7 mm
leg = 25 mm
bridge = 12 mm
top_h = 200 mm       # the glass's top edge above the cheeks' bottom
upper_h = 130 mm
lower_h = 30 mm

def cheek() -> solid {
    # x: out from the glass's inner face (x = 0), y: up from the cheek's bottom
    p = Polygon([(0, 0), (depth, 0), (depth, 150 mm), (20 mm, top_h + bridge),
                 (-gap - 6 mm, top_h + bridge), (-gap - 6 mm, top_h - leg), (-gap, top_h - leg),
                 (-gap, top_h), (0, top_h)])
    Fillet([p.points[2], p.points[3], p.points[4]], 4 mm)
    Fillet([p.points[5], p.points[6]], 2 mm)
    up = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                      cx=depth / 2, cy=upper_h)
    low = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                       cx=depth / 2, cy=lower_h)
    hole paw {
        pad = Ellipse(center=(55 mm, 70 mm), rx=14 mm, ry=11 mm)
        t1 = Circle(center=(38 mm, 89 mm), radius=5 mm)
        t2 = Circle(center=(49 mm, 95 mm), radius=5 mm)
        t3 = Circle(center=(61 mm, 95 mm), radius=5 mm)
        t4 = Circle(center=(72 mm, 89 mm), radius=5 mm)
    }
}

def ring(hole_d=64 mm, name="") -> solid {
    # x: across, between the cheeks (tabs' tips at +-(inside / 2 + t)); y: out from the glass
    body = Rectangle(center=(0, depth / 2), width=inside + 2 * t, height=depth)
    left_tabs = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=-inside / 2 - t, cy=depth / 2)
    right_tabs = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                              rotation=-90 deg, cx=inside / 2 + t, cy=depth / 2)
    hole bottle {
        c = Circle(center=(0, 50 mm), diameter=hole_d)
    }
    if name != "" {
        drawing label {
            n = Text(name, position=(0, 91 mm), size=7 mm, valign="middle")
        }
    }
}

assembly bottle_holder {
    left_cheek = cheek()
    right_cheek = cheek()
    upper = ring(hole_d=64 mm, name="PEANUT")
    lower = ring(hole_d=34 mm)

    # flat on the sheet, side by side
    RightOf(right_cheek, left_cheek, gap=5 mm)
    AlignBottom(right_cheek, left_cheek)
    RightOf(upper, right_cheek, gap=5 mm)
    AlignBottom(upper, right_cheek)
    RightOf(lower, upper, gap=5 mm)
    AlignBottom(lower, upper)

    # assembled: the glass's inner face is y = 0, the tank inside toward +y; both cheeks'
    # drawn faces toward +x, their drawing's +x out from the glass (+y)
    Place(left_cheek, position=(-inside / 2 - t, 0, 0), face="right", up="up")
    Place(right_cheek, position=(inside / 2, 0, 0), face="right", up="up")
    Place(upper, position=(0, 0, upper_h - t / 2))
    Place(lower, position=(0, 0, lower_h - t / 2))

    # the request's numbers
    assert left_cheek.p.bb.width == 100 mm + 7 mm + 6 mm, "100 deep plus the hook"
    assert left_cheek.p.points[7].x - left_cheek.p.points[6].x == 0 and
        left_cheek.p.points[8].x - left_cheek.p.points[7].x == 7 mm, "7 mm glass gap"
    assert left_cheek.p.points[7].y - left_cheek.p.points[6].y == 25 mm, "25 mm outer leg"
    assert left_cheek.p.bb.height - top_h == 12 mm, "12 mm bridge"
    assert gap - glass >= 1 mm, "clearance on the glass"
    assert upper.bottle.c.diameter == 64 mm and lower.bottle.c.diameter == 34 mm, "holes"
    assert upper.bottle.c.diameter - 62 mm >= 1 mm, "the bottle drops in"
    assert lower.bottle.c.diameter - 30 mm >= 2 mm and lower.bottle.c.diameter < 62 mm,
        "the cap passes, the shoulder rests"
    assert left_cheek.up.slot[0].bb.center_y - left_cheek.low.slot[0].bb.center_y == 130 mm - 30 mm,
        "rings 30 and 130 mm up"
    assert upper.body.bb.width - 2 * t == 82 mm, "82 mm between the cheeks"
    # the paw stays clear of the mortises and the front edge
    assert left_cheek.paw.bb.bottom - (left_cheek.low.slot[0].bb.top) >= 5 mm, "paw over the low ring"
    assert left_cheek.up.slot[0].bb.bottom - left_cheek.paw.bb.top >= 5 mm, "paw under the top ring"
}
