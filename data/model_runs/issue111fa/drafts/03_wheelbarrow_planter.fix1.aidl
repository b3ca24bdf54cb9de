# Request: a wheelbarrow planter for the patio (herbs), 6 mm exterior ply.
# - Tray: an open finger-jointed box 200 long x 120 wide x 70 high outside (15 mm fingers),
#   "HERBS" engraved filled, 22 mm bold, in the middle of the front wall, and four 8 mm
#   drainage holes along the bottom's centre line, 40 mm apart.
# - Two frame rails under the tray, 48 mm apart centre to centre, glued into the bottom by
#   three 30 mm tenons each (mortises in the bottom, 0.1 mm clearance) over the middle 180 mm.
#   Each rail: a 30 mm deep bar from the wheel end to the tray's back end, a round eye (R15)
#   60 mm in front of the tray carrying the 6 mm dowel axle (6.2 mm hole), a handle running
#   130 mm on behind the tray, rising to a R10 grip, and a 22 mm leg under the back of the
#   tray reaching down to where the wheel stands (R8 fillets where it meets the bar).
# - Wheel: 100 mm diameter, 6.2 mm hub hole, six spoke windows (R14 to R38), corners R3.
# - Six 25 mm washers (6.2 mm hole), three each side, space the wheel in the middle.

# FIX after the first valid program: W0517 said the wheel runs 6 mm into the tray's end wall
# (my request put a 50 mm radius wheel 40 mm in front of the tray): the axle now sits 60 mm in
# front (10 mm clear); the handle's rise now starts 5 mm behind the tray (W0517: it touched the
# tray bottom's back corner by 0.013 mm).

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 6 mm

def rail() -> solid {
    bar = Rectangle(bottom_left=(-60, -30), width=270, height=30)
    eye = Circle(center=(-60, -15), radius=15)
    strip = Rectangle(bottom_left=(10, 0), width=180, height=6)
    handle = Hull(Circle(center=(205, -15), radius=15), Circle(center=(320, -5), radius=10))
    leg = Rectangle(bottom_left=(160, -65), width=22, height=65)
    Fillet([leg.left, bar.bottom], 8)
    Fillet([leg.right, bar.bottom], 8)
    hole axle {
        c = Circle(center=(-60, -15), diameter=6.2)
    }
    tenons = tab_and_slot(part="tab", length=180 mm, thickness=6 mm, tabs=3, tab=30 mm,
                          screw=0, cx=100 mm, cy=6 mm)
}

assembly wheelbarrow {
    box = finger_box(length=200 mm, depth=120 mm, height=70 mm, thickness=6 mm, finger=15 mm,
                     closed=false)

    mortise_a = tab_and_slot(part="slot", length=180 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, clearance=0.1 mm, cx=0 mm, cy=24 mm)
    mortise_b = tab_and_slot(part="slot", length=180 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, clearance=0.1 mm, cx=0 mm, cy=-24 mm)
    hole drain {
        for i in range(4) {
            d = Circle(center=(-60 + 40 * i, 0), diameter=8)
        }
    }
    drawing name {
        t = Text("HERBS", position=(0, 0), size=22, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(drain, box.bottom)
    CenterInside(name, box.front)
    CutInto(mortise_a, box.bottom)
    CutInto(mortise_b, box.bottom)
    CutInto(drain, box.bottom)
    CutInto(name, box.front)

    rail_a = rail()
    rail_b = rail()

    solid wheel {
        rim = Circle(center=(0, 0), diameter=100)
        hole hub {
            c = Circle(center=(0, 0), diameter=6.2)
        }
        for i in range(6) {
            hole spoke {
                w = Sector(center=(0, 0), radius=38, inner_radius=14, start_angle=i * 60 deg + 14 deg,
                           end_angle=i * 60 deg + 46 deg)
            }
        }
        Fillet(3)
    }

    for i in range(6) {
        sp = washer(outer=25 mm, inner=6.2 mm)
    }

    # laid out flat: rails under the net, the wheel and washers to the right of the rails
    Below(rail_a, box, gap=10)
    AlignLeft(rail_a, box)
    Below(rail_b, rail_a, gap=6)
    AlignLeft(rail_b, rail_a)
    RightOf(wheel, rail_a, gap=10)
    AlignTop(wheel, rail_a)
    Below(sp[0], wheel, gap=6)
    AlignLeft(sp[0], wheel)
    for i in range(1, 6) {
        RightOf(sp[i], sp[i - 1], gap=4)
        AlignTop(sp[i], sp[0])
    }

    # assembled: the tray stands on z = 0 (its bottom's underside), rails under it along x,
    # the wheel between the rails' eyes with three washers each side
    Place(rail_a, position=(-100, 27, 0), face="front", up="up")
    Place(rail_b, position=(-100, -21, 0), face="front", up="up")
    Place(wheel, position=(-160, 3, -15), face="front", up="up")
    ys = [9, 15, 21, -3, -9, -15]
    for i in range(6) {
        Place(sp[i], position=(-160, ys[i], -15), face="front", up="up")
    }

    assert box.length == 200 mm and box.depth == 120 mm and box.height == 70 mm, "tray size"
    assert mortise_a.slot[0].bb.center_y - mortise_b.slot[0].bb.center_y == 48 mm, "rails 48 apart"
    assert len(mortise_a.slot) == 3, "three tenons a rail"
    assert drain.d[1].center.x - drain.d[0].center.x == 40 mm, "drain holes 40 apart"
    assert distance(drain, mortise_a) >= 5 mm and distance(drain, mortise_b) >= 5 mm, "drains clear of the mortises"
    assert wheel.rim.diameter == 100 mm, "100 mm wheel"
    assert rail_a.leg.bb.bottom == rail_a.axle.c.center.y - 50 mm, "leg reaches the wheel's ground"
    # the tray spans 200 mm over the rail, the tenon strip its middle 180
    assert (rail_a.strip.bb.center_x - 200 mm / 2) - rail_a.axle.c.center.x == 60 mm, "axle 60 in front of the tray"
    assert rail_a.handle.bb.right - (rail_a.strip.bb.center_x + 200 mm / 2) == 130 mm, "handle 130 behind the tray"
    assert 3 * 6 mm == (48 mm - 6 mm - 6 mm) / 2, "three washers fill each side"
    assert len(sp) == 6, "six washers"
}
