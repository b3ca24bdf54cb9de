# Request: a socket rail for my drawer. Ten 3/8-inch-drive metric sockets, 8 to 17 mm,
# stand upright in one row. 3 mm ply: a deck 300 x 70 with one round hole per socket,
# the socket's outside diameter + 1 mm (8: 17, 9: 17, 10: 17, 11: 17.5, 12: 18, 13: 19,
# 14: 20, 15: 21, 16: 22.5, 17: 24 mm), on a 28 mm pitch, the size engraved under each hole.
# The deck stands 18 mm above a 300 x 70 base on a front and a back skirt (280 long,
# 5 mm in from the long edges), each glued into both by three 20 mm tenons in mortises.
# "3/8 DRIVE METRIC" engraved filled on the front skirt's outside. Two M4 countersunk
# screws fix the base to the drawer, under the first and last socket holes (the driver
# goes through them).

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
thickness 3 mm

t = 3 mm
deck_w = 300 mm
deck_d = 70 mm
rise = 18 mm           # clear height between base top and deck bottom
skirt_l = 280 mm
skirt_in = 5 mm        # skirt outer face from the long edge
pitch = 28 mm
sizes = [8, 9, 10, 11, 12, 13, 14, 15, 16, 17]
od = [17, 17, 17, 17.5, 18, 19, 20, 21, 22.5, 24]
hole_y = 6 mm          # socket row above the deck's middle
skirt_y = deck_d / 2 - skirt_in - t / 2    # skirt mid-plane from the deck's middle
x0 = -(len(sizes) - 1) * pitch / 2

assembly socket_rail {
    solid deck {
        plate = Rectangle(center=(0, 0), width=deck_w, height=deck_d)
        hole sockets {
            for i in range(len(sizes)) {
                c = Circle(center=(x0 + i * pitch, hole_y), diameter=od[i] + 1 mm)
            }
        }
        drawing labels {
            for i in range(len(sizes)) {
                n = Text(str(sizes[i]), position=(x0 + i * pitch, -16), size=6, valign="middle")
            }
        }
        front_mortise = tab_and_slot(part="slot", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                     screw=0, cx=0 mm, cy=-skirt_y)
        back_mortise = tab_and_slot(part="slot", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                    screw=0, cx=0 mm, cy=skirt_y)
        assert len(sockets.c) == 10, "ten sockets"
        assert sockets.c[9].diameter == 25 mm, "17 mm socket: 24 + 1"
        assert sockets.c[3].diameter == 18.5 mm, "11 mm socket: 17.5 + 1"
        assert sockets.c[1].center.x - sockets.c[0].center.x == 28 mm, "28 mm pitch"
        assert distance(sockets.c[8], sockets.c[9]) >= 3 mm, "web between the largest holes"
        assert sockets.bb.bottom >= front_mortise.bb.top + 3 mm, "holes clear the front mortises"
        assert sockets.bb.top <= back_mortise.bb.bottom - 3 mm, "holes clear the back mortises"
        assert distance(labels, sockets) >= 1.5 mm, "labels clear of the holes"
        assert labels.bb.bottom >= front_mortise.bb.top + 1.5 mm, "labels clear of the mortises"
    }

    solid base {
        plate = Rectangle(center=(0, 0), width=deck_w, height=deck_d)
        front_mortise = tab_and_slot(part="slot", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                     screw=0, cx=0 mm, cy=-skirt_y)
        back_mortise = tab_and_slot(part="slot", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                    screw=0, cx=0 mm, cy=skirt_y)
        left_screw = clearance_hole(size=4, cx=x0, cy=hole_y)
        right_screw = clearance_hole(size=4, cx=-x0, cy=hole_y)
        Countersink([left_screw, right_screw], diameter=8 mm)
    }

    solid front_skirt {
        board = Rectangle(center=(0, 0), width=skirt_l, height=rise + 2 * t)
        top_tenons = tab_and_slot(part="tab", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, cx=0 mm, cy=rise / 2 + t)
        bottom_tenons = tab_and_slot(part="tab", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                     screw=0, rotation=180 deg, cx=0 mm, cy=-rise / 2 - t)
        drawing title {
            w = Text("3/8 DRIVE METRIC", position=(0, 0), size=8, font="sans:Bold",
                     valign="middle", fill=true)
        }
        assert title.bb.height <= rise - 4 mm, "title fits the visible face"
    }

    solid back_skirt {
        board = Rectangle(center=(0, 0), width=skirt_l, height=rise + 2 * t)
        top_tenons = tab_and_slot(part="tab", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, cx=0 mm, cy=rise / 2 + t)
        bottom_tenons = tab_and_slot(part="tab", length=skirt_l, thickness=t, tabs=3, tab=20 mm,
                                     screw=0, rotation=180 deg, cx=0 mm, cy=-rise / 2 - t)
    }

    # flat layout on the sheet
    Below(base, deck, gap=10)
    AlignLeft(base, deck)
    Below(front_skirt, base, gap=10)
    AlignLeft(front_skirt, base)
    Below(back_skirt, front_skirt, gap=10)
    AlignLeft(back_skirt, front_skirt)

    # assembled: base on the drawer floor, skirts standing in its mortises, deck on top
    Place(base, position=(0, 0, 0), face="up")
    Place(front_skirt, position=(0, -skirt_y + t / 2, t + rise / 2), face="front", up="up")
    Place(back_skirt, position=(0, skirt_y - t / 2, t + rise / 2), face="back", up="up")
    Place(deck, position=(0, 0, t + rise), face="up")

    assert deck.plate.width == 300 mm and deck.plate.height == 70 mm, "deck 300 x 70"
    assert front_skirt.board.height - 2 * t == 18 mm, "deck 18 mm above the base"
    assert front_skirt.board.width == 280 mm, "skirts 280 long"
}
