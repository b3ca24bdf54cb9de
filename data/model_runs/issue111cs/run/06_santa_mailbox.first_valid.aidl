# Request (holidays): a "Letters to Santa" mailbox for the mantelpiece, 3 mm plywood.
# Front and back: 160 mm wide, 150 mm up to a semicircular arch of 80 mm radius (230 mm tall).
# Front: a 110 x 10 mm letter slot 50 mm above the middle of the square part, "LETTERS TO
# SANTA" engraved filled (serif bold, 11 mm) along the arch, a filled 5-point star (24 mm)
# under it, "NORTH POLE" engraved filled (10 mm) below the slot. Back: a 70 mm round opening
# to take the letters out. Two sides (150 mm tall, the box 120 mm deep overall) and a bottom,
# inset 5 mm from the front's edges, glued into mortises in the front and back by 40 mm tabs.
# Roof: a living-hinge band bent over the arches (inside radius 80 mm), 120 mm wide.
# A flag on the right side turning on an M4 bolt: a 12 mm stem 80 mm from the pivot to its
# top with a 45 x 30 mm banner at the top.

import "std/joints.aidl"
import "std/plates.aidl"
import "std/fasteners.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 4 mm
param w = 160 mm, min = 120 mm, max = 220 mm
param h = 150 mm, min = 100 mm, max = 200 mm
param depth = 120 mm, min = 80 mm, max = 160 mm
param inset = 5 mm, min = 4 mm, max = 10 mm

# the sides' and bottom's middles, in an end panel's frame (its square part centred on 0, 0)
side_x = w / 2 - inset - t / 2
bottom_y = -h / 2 + inset + t / 2
roof_len = pi * (w / 2 + t / 2)

def end_panel() -> solid {
    square = Rectangle(center=(0, 0), width=w, height=h)
    arch = Circle(center=(0, h / 2), radius=w / 2)
    hole trim { r = Rectangle(center=(0, h / 2 - w / 4), width=w + 2, height=w / 2) }
    left_slot = tab_and_slot(part="slot", length=h, thickness=t, tabs=2, tab=40 mm, screw=0,
                             rotation=90 deg, cx=-side_x, cy=0 mm)
    right_slot = tab_and_slot(part="slot", length=h, thickness=t, tabs=2, tab=40 mm, screw=0,
                              rotation=90 deg, cx=side_x, cy=0 mm)
    bottom_slot = tab_and_slot(part="slot", length=w - 2 * inset - 2 * t, thickness=t, tabs=2,
                               tab=40 mm, screw=0, cx=0 mm, cy=bottom_y)
}

def side_panel() -> solid {
    body = Rectangle(center=(0, 0), width=depth, height=h)
    front_tabs = tab_and_slot(part="tab", length=h, thickness=t, tabs=2, tab=40 mm, screw=0,
                              rotation=90 deg, cx=-depth / 2, cy=0 mm)
    back_tabs = tab_and_slot(part="tab", length=h, thickness=t, tabs=2, tab=40 mm, screw=0,
                             rotation=-90 deg, cx=depth / 2, cy=0 mm)
}

assembly santa_mailbox {
    solid front {
        p = end_panel()
        hole letters { s = Slot(center=(0, 50), length=110, width=10) }
        drawing words {
            ring = Circle(center=(0, h / 2), radius=58, construction=true)
            top = Text("LETTERS TO SANTA", along=ring, size=11, font="serif:Bold", fill=true)
            star = Star(center=(0, h / 2 + 22), points=5, outer_radius=12, inner_radius=5,
                        fill=true)
            pole = Text("NORTH POLE", position=(0, 20), size=10, font="serif:Bold",
                        valign="middle", fill=true)
        }
    }

    solid back {
        p = end_panel()
        hole reach { c = Circle(center=(0, 0), diameter=70) }
    }

    left_side = side_panel()
    solid right_side {
        s = side_panel()
        pivot = clearance_hole(size=4, cx=-30 mm, cy=-20 mm)
    }

    solid bottom {
        body = Rectangle(center=(0, 0), width=w - 2 * inset - 2 * t, height=depth)
        front_tabs = tab_and_slot(part="tab", length=w - 2 * inset - 2 * t, thickness=t, tabs=2,
                                  tab=40 mm, screw=0, rotation=180 deg, cx=0 mm, cy=-depth / 2)
        back_tabs = tab_and_slot(part="tab", length=w - 2 * inset - 2 * t, thickness=t, tabs=2,
                                 tab=40 mm, screw=0, cx=0 mm, cy=depth / 2)
    }

    solid roof {
        band = Rectangle(center=(0, 0), width=roof_len, height=depth)
        flex = living_hinge(width=roof_len - 6 mm, height=depth, pitch=3 mm, cut=20 mm,
                            bridge=4 mm, cx=0 mm, cy=0 mm)
    }

    solid flag {
        stem = RoundedRectangle(center=(0, 36), width=12, height=88, corner_radius=6)
        banner = Rectangle(center=(22.5, 65), width=45, height=30)
        pivot = clearance_hole(size=4, cx=0 mm, cy=0 mm)
    }

    # flat on the sheet
    RightOf(back, front, gap=6)
    AlignBottom(back, front)
    RightOf(left_side, back, gap=6)
    AlignBottom(left_side, back)
    RightOf(right_side, left_side, gap=6)
    AlignBottom(right_side, left_side)
    Above(bottom, left_side, gap=6)
    AlignLeft(bottom, left_side)
    Above(roof, front, gap=6)
    AlignLeft(roof, front)
    RightOf(flag, bottom, gap=6)
    AlignBottom(flag, bottom)

    # assembled: y is the depth (front at -depth/2), z up from the mantelpiece
    Place(front, position=(0, -depth / 2 + t, h / 2), face="front", up="up")
    Place(back, position=(0, depth / 2 - t, h / 2), face="back", up="up")
    Place(left_side, position=(-w / 2 + inset + t, 0, h / 2), face="left", up="up")
    Place(right_side, position=(w / 2 - inset - t, 0, h / 2), face="right", up="up")
    Place(bottom, position=(0, 0, inset), face="up")
    # the roof stood up at the arch's left end, its top face inward, then bent over the arch
    Place(roof, position=(-w / 2 - t, 0, h + roof_len / 2), face="right", up="front")
    Bend(roof, at=0, angle=180 deg, radius=w / 2)
    # the flag on the right side's bolt, outside it
    Place(flag, position=(w / 2 - inset, -30, h / 2 - 20), face="right", up="up")

    # the request's numbers
    assert front.p.square.width == 160 mm and front.p.arch.radius == 80 mm
    assert front.p.bb.height == 230 mm
    assert front.letters.s.length == 110 mm and front.letters.s.width == 10 mm
    assert front.letters.s.center.y - front.p.square.center.y == 50 mm
    assert front.words.top.size == 11 mm and front.words.pole.size == 10 mm
    assert front.words.star.bb.height <= 24 mm
    assert back.reach.c.diameter == 70 mm
    assert left_side.body.height == 150 mm and left_side.body.width == 120 mm
    assert roof.band.height == 120 mm
    assert flag.banner.width == 45 mm and flag.banner.height == 30 mm
    assert flag.stem.bb.top - flag.pivot.c.center.y == 80 mm
    assert right_side.pivot.c.diameter == flag.pivot.c.diameter
    # the arch text stays above the letter slot
    assert front.words.top.bb.bottom >= front.letters.s.bb.top + 5 mm
}
