# Request (electronics): a handheld 3-element Yagi for 2 m fox hunting (146 MHz), tape-measure
# elements, from 6 mm ply. The boom is 1000 x 50 mm, cut in two 500 mm halves joined by a
# glued sliding dovetail (3 tails, 12 mm deep). The elements are 25 mm steel tape laid across
# the boom's top face: reflector 1054 mm at 60 mm from the rear end, driven element 902 mm
# (two halves with a 12 mm gap) at 428 mm, director 826 mm at 961 mm. Each element is held
# by two cable ties, each through a pair of 2.5 x 6 mm slots 33 mm apart (centre to centre)
# straddling the tape, the two ties 15 mm either side of the boom's centre line. A 9.6 mm
# hole for a BNC bulkhead on the centre line 38 mm behind the driven element. Engraved:
# each element's name and length beside it, "2 m FOX" at the rear end. A D-handle under the
# boom: 120 x 100 mm, bottom corners R20, a 95 x 32 mm hand hole 40 mm below the boom,
# glued into the boom by 2 tabs 30 mm wide, its front end 200 mm from the boom's rear end.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
boom_l = 1000 mm
boom_w = 50 mm
split = 500 mm
stations = [60 mm, 428 mm, 961 mm]
names = ["REF", "DE", "DIR"]
lengths = [1054, 902, 826]
tape = 25 mm
tie_pitch = 33 mm      # between the two slots of one tie
tie_y = 15 mm          # each tie from the centre line
grip_x = 200 mm        # the handle's start from the rear end
grip_w = 120 mm

def tie_slots(s) = [Rectangle(center=(s + sx * tie_pitch / 2, sy * tie_y), width=2.5,
                              height=6) for sx in [-1, 1] for sy in [-1, 1]]

assembly yagi {
    solid rear {
        body = Rectangle(corner=(0, -boom_w / 2), opposite=(split + 12 mm, boom_w / 2))
        tails = dovetail(part="tail", length=boom_w, depth=12 mm, tails=3, angle=10 deg,
                         rotation=-90 deg, cx=split, cy=0 mm)
        hole ties {
            r = tie_slots(stations[0])
            d = tie_slots(stations[1])
        }
        hole bnc {
            c = Circle(center=(stations[1] - 38 mm, 0), diameter=9.6)
        }
        grip_slots = tab_and_slot(part="slot", length=grip_w, thickness=t, tabs=2, tab=30 mm,
                                  screw=0, rotation=0 deg, cx=grip_x + grip_w / 2, cy=0 mm)
        drawing labels {
            for i in range(2) {
                l = Text(f"{names[i]} {lengths[i]}", position=(stations[i] + 26 mm, 0),
                         size=5, rotation=90 deg, valign="middle")
            }
            fox = Text("2 m FOX", position=(24 mm, 0), size=6, rotation=90 deg,
                       valign="middle")
        }
    }

    solid front {
        body = Rectangle(corner=(split, -boom_w / 2), opposite=(boom_l, boom_w / 2))
        sockets = dovetail(part="socket", length=boom_w, depth=12 mm, tails=3, angle=10 deg,
                           rotation=-90 deg, cx=split, cy=0 mm)
        hole ties {
            r = tie_slots(stations[2])
        }
        drawing labels {
            l = Text(f"{names[2]} {lengths[2]}", position=(stations[2] - 26 mm, 0),
                     size=5, rotation=90 deg, valign="middle")
        }
    }

    solid grip {
        body = RoundedRectangle(corner=(grip_x, -100 mm), opposite=(grip_x + grip_w, 0),
                                corner_radii=[0 mm, 0 mm, 20 mm, 20 mm])
        tabs = tab_and_slot(part="tab", length=grip_w, thickness=t, tabs=2, tab=30 mm,
                            screw=0, rotation=0 deg, cx=grip_x + grip_w / 2, cy=0 mm)
        hole hand {
            s = Slot(center=(grip_x + grip_w / 2, -t - 40 mm), length=95, width=32)
        }
    }

    # flat on the sheet
    Below(front, rear, gap=10)
    AlignLeft(front, rear)
    Below(grip, front, gap=10)
    AlignLeft(grip, front)

    # assembled: the boom flat, the handle hanging under it on the centre line
    Place(rear, position=(0, 0, 0), face="up")
    Place(front, position=(0, 0, 0), face="up")
    Place(grip, position=(0, t / 2, t), face="front", up="up")

    assert front.body.bb.right - rear.body.bb.left == 1000 mm, "boom 1000 long"
    assert rear.body.bb.height == 50 mm, "boom 50 wide"
    assert split - rear.body.bb.left == 500 mm and front.body.bb.right - split == 500 mm,
        "two 500 halves"
    assert rear.ties.r[0].center.x + tie_pitch / 2 - rear.body.bb.left == 60 mm, "reflector at 60"
    assert rear.ties.d[0].center.x + tie_pitch / 2 - rear.body.bb.left == 428 mm, "DE at 428"
    assert front.ties.r[0].center.x + tie_pitch / 2 - rear.body.bb.left == 961 mm, "director at 961"
    assert tie_pitch - 2.5 mm >= tape + 2 * 1 mm, "the tape fits between a tie's slots"
    assert stations[1] - rear.bnc.c.center.x == 38 mm, "BNC 38 behind the DE"
    assert grip.body.bb.width == 120 mm and grip.body.bb.height - t == 100 mm, "handle 120 x 100"
    assert grip.body.bb.left - rear.body.bb.left == 200 mm, "handle 200 from the rear end"
    assert -t - grip.hand.s.center.y - 32 mm / 2 == 40 mm - 32 mm / 2, "hand hole 40 below"
    assert len(rear.ties.r) + len(rear.ties.d) + len(front.ties.r) == 12, "2 ties x 2 slots x 3"
}
