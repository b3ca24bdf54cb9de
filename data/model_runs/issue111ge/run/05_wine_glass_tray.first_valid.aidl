# Request (parties): a caddy to carry six filled wine glasses round a garden party. 6 mm ply.
# - Tray 320 x 220 mm, corners R20. Six stem slots, three from each long edge at 100 mm pitch
#   (centred), each 12 mm wide and running 45 mm in from the edge to a 14 mm round seat; the
#   slot mouths rounded R3. The glass stands in its slot: the bowl (up to 85 mm across) above the
#   tray, the foot below.
# - A centre handle along the tray's length: 300 mm long, 40 mm tall at the ends, arching to 90 mm
#   in the middle, arch corners R8; a 100 x 30 mm round-ended hand hole centred 55 mm up; "CHEERS"
#   engraved filled in bold italic serif, 14 mm, under the hand hole. Glued with three 30 mm
#   tabs into closed slots in the tray (0.1 mm clearance).

import "std/joints.aidl"

thickness 6 mm

param clear = 0.1 mm, min = 0 mm, max = 0.3 mm

pitch = 100 mm
slot_len = 45 mm
bowl = 85 mm

assembly caddy {
    solid tray {
        body = RoundedRectangle(center=(0, 0), width=320, height=220, corner_radius=20)
        for i in range(3) {
            hole stem_back {
                s = Slot(start=(-100 + 100 * i, 111), end=(-100 + 100 * i, 65), width=12)
                seat = Circle(center=(-100 + 100 * i, 65), diameter=14)
            }
            hole stem_front {
                s = Slot(start=(-100 + 100 * i, -111), end=(-100 + 100 * i, -65), width=12)
                seat = Circle(center=(-100 + 100 * i, -65), diameter=14)
            }
        }
        Fillet([[body, stem_back[i].s] for i in range(3)] + [[body, stem_front[i].s] for i in range(3)], 3)
        handle_slots = tab_and_slot(part="slot", length=300 mm, thickness=6 mm, tabs=3, tab=30 mm,
                                    screw=0, clearance=clear, cx=0 mm, cy=0 mm)
    }

    solid handle {
        base = Line((-150, -6), (150, -6))
        right = Line((150, -6), (150, 40))
        top = Arc(start=(150, 40), through=(0, 90), end=(-150, 40))
        left = Line((-150, 40), (-150, -6))
        Fillet(top.start, 8)
        Fillet(top.end, 8)
        hole grip {
            s = Slot(center=(0, 55), length=100, width=30)
        }
        feet = tab_and_slot(part="tab", length=300 mm, thickness=6 mm, tabs=3, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-6 mm)
        drawing words {
            t = Text("CHEERS", position=(0, 14), size=14, font="serif:Bold Italic", fill=true)
        }
    }

    # on the sheet
    Above(handle, tray, gap=5)
    AlignCenterX(handle, tray)

    # in 3D: the handle stands on the tray's centre line, its engraving to the front
    Place(handle, position=(0, 3, 6), face="front", up="up")

    # the request's numbers
    assert tray.body.bb.width == 320 mm and tray.body.bb.height == 220 mm, "tray 320 x 220"
    assert len(tray.stem_back) + len(tray.stem_front) == 6, "six glasses"
    assert tray.stem_back[1].seat.center.x - tray.stem_back[0].seat.center.x == 100 mm, "100 pitch"
    assert tray.body.bb.top - tray.stem_back[0].seat.center.y == 45 mm, "slots 45 in"
    assert tray.stem_front[0].s.width == 12 mm and tray.stem_front[0].seat.diameter == 14 mm, "12 slot, 14 seat"
    assert handle.top.through.y == 90 mm and handle.right.end.y == 40 mm, "handle 40 at the ends, 90 in the middle"
    assert handle.base.length == 300 mm, "handle 300 long"
    assert handle.grip.s.length == 100 mm and handle.grip.s.width == 30 mm and handle.grip.s.center.y == 55 mm, "hand hole"
    # glasses clear of each other and of the handle
    assert pitch > bowl + 10 mm, "bowls clear of each other"
    assert tray.stem_back[0].seat.center.y - bowl / 2 - 3 mm >= 15 mm, "bowls clear of the handle"
    # wood above the hand hole: the arch of radius 250 through the ends, at the hole's ends
    assert 90 mm - 250 mm + sqrt((250 mm) ** 2 - (65 mm) ** 2) - 70 mm >= 10 mm, "wood above the hand hole"
    assert handle.words.bb.top <= handle.grip.bb.bottom - 4 mm, "CHEERS under the hand hole"
}
