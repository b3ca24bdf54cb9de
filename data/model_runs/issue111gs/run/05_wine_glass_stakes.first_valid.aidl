# Request: wine-glass stakes for a garden party, 6 mm oak ply, one per guest: ANNA,
# BEN, CARLA and DEV.
# - Each stake is 300 mm from its tip to the top of the tenon: a 30 mm wide shank
#   ending in a point 80 mm long; the guest's name engraved in filled bold letters
#   12 mm tall along the shank (reading upward), kept at least 10 mm from the point
#   and from the top.
# - On top of each stake a round glass rest 80 mm across, glued onto the stake by one
#   20 mm through-tenon (flush with its top), the stake's middle 25 mm behind the
#   rest's centre. The glass stem slides in from the front through a 10 mm slot that
#   ends in a 13 mm round hole at the centre.
# Slots 0.1 mm over for glue.

units mm
thickness 6 mm
import "std/joints.aidl"

names = ["ANNA", "BEN", "CARLA", "DEV"]

def stake(who="NAME") -> solid {
    # seen from the front: x across, y up from the tip
    shank = Rectangle(center=(0, 190), width=30, height=220)
    point = Polygon([(-15, 80), (15, 80), (0, 0)])
    tenon = tab_and_slot(part="tab", length=30, thickness=6, tabs=1, tab=20, screw=0,
                         cx=0, cy=300)
    drawing label {
        t = Text(who, position=(0, 190), size=12, rotation=90 deg, font="sans:Bold",
                 valign="middle", fill=true, max_width=150)
    }
}

def rest() -> solid {
    # seen from above, the front at -y
    disc = Circle(center=(0, 0), diameter=80)
    hole stem {
        seat = Circle(center=(0, 0), diameter=13)
        way = Rectangle(center=(0, -21), width=10, height=42, overrun=true)
    }
    mortise = tab_and_slot(part="slot", length=30, thickness=6, tabs=1, tab=20, screw=0,
                           clearance=0.1, cx=0, cy=25)
}

assembly glass_stakes {
    for i in range(4) {
        s = stake(who=names[i])
        r = rest()
        s.bb.center_x == i * 45
        s.bb.bottom == 0
        r.bb.center_x == 200 + (i % 2) * 90
        r.bb.bottom == (i // 2) * 90
        Place(s, position=(i * 150, 28, 0), face="front", up="up")
        Place(r, position=(i * 150, 0, 294), face="up", up="back")
    }

    # the request's numbers
    assert len(s) == 4 and len(r) == 4, "four guests"
    assert s[0].tenon.bb.top - s[0].point.bb.bottom == 300 mm, "300 mm tip to tenon top"
    assert s[0].shank.width == 30 mm, "shank 30 wide"
    assert s[0].point.bb.height == 80 mm, "point 80 long"
    assert r[0].disc.diameter == 80 mm, "rest 80 across"
    assert r[0].stem.way.width == 10 mm and r[0].stem.seat.diameter == 13 mm, "stem slot 10, seat 13"
    assert r[0].mortise.slot[0].bb.center_y - r[0].disc.center.y == 25 mm, "stake 25 behind the centre"
    for i in range(4) {
        assert s[i].label.t.size <= 12 mm, "names at most 12 mm"
        assert s[i].label.bb.bottom - s[i].point.bb.top >= 10 mm, "name clear of the point"
        assert s[i].shank.bb.top - 6 mm - s[i].label.bb.top >= 10 mm, "name clear of the top"
        assert s[i].label.bb.width <= s[i].shank.width - 6 mm, "name inside the shank"
    }
}
