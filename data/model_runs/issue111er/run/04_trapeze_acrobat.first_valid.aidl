# Request: the old squeeze-stick acrobat toy, in 4 mm birch ply. Squeeze the sticks'
# lower ends and the twisted string between their tops flips the acrobat over the bar.
# - Two uprights 280 x 20, round-topped (10 mm radius), each with two 2.5 mm string
#   holes 10 and 20 mm below the top, and a mortise 80 mm above the bottom for the
#   crossbar's tenon, 0.5 mm loose so the sticks can rock on it.
# - A crossbar 16 tall, 110 between the uprights' inner faces, a 10 mm tenon at each
#   end through the upright (flush with its outer face).
# - The acrobat, 2 parts joined at the shoulder by a 3 mm dowel (3.2 mm holes):
#   a body (head 22 mm across, torso 22 x 38 with 6 mm radii, two legs 9 wide,
#   splayed 10 degrees, 50 long) with engraved eyes and a smile; and the arms, a bar
#   12 wide whose hands (18 mm discs) are 80 mm apart, each hand with two 2.5 mm string
#   holes 8 mm apart one above the other.

units mm
t = 4 mm
thickness t
kerf 0.15 mm

import "std/joints.aidl"

stick_h = 280 mm
stick_w = 20 mm
bar_h = 16 mm
inner = 110 mm       # between the uprights' inner faces
bar_z = 80 mm        # mortise centre above the bottom
hands = 80 mm        # between the hands' centres
hang_z = 250 mm      # the hands' centres above the bottom (3D)

def upright() -> solid {
    body = RoundedRectangle(center=(0, stick_h / 2), width=stick_w, height=stick_h,
                            corner_radii=[10 mm, 10 mm, 2 mm, 2 mm])
    hole string {
        a = Circle(center=(0, stick_h - 10 mm), diameter=2.5 mm)
        b = Circle(center=(0, stick_h - 20 mm), diameter=2.5 mm)
    }
    mortise = tab_and_slot(part="slot", length=bar_h, thickness=t, tabs=1, tab=10 mm,
                           screw=0, clearance=0.5 mm, rotation=90 deg, cx=0, cy=bar_z)
    Fixed(body)
    Fixed(string)
}

assembly acrobat_toy {
    stick_l = upright()
    stick_r = upright()

    solid crossbar {
        body = Rectangle(center=(0, bar_z), width=inner + 2 * t, height=bar_h)
        left_tenon = tab_and_slot(part="tab", length=bar_h, thickness=t, tabs=1, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=-(inner / 2 + t), cy=bar_z)
        right_tenon = tab_and_slot(part="tab", length=bar_h, thickness=t, tabs=1, tab=10 mm,
                                   screw=0, rotation=-90 deg, cx=inner / 2 + t, cy=bar_z)
        Fixed(body)
    }

    solid body {
        head = Circle(center=(0, 0), diameter=22 mm)
        torso = RoundedRectangle(center=(0, -32 mm), width=22 mm, height=38 mm, corner_radius=6 mm)
        leg_l = Rectangle(center=(-6 mm - 25 mm * sin(10 deg), -48 mm - 25 mm * cos(10 deg)),
                          width=9 mm, height=50 mm, rotation=-10 deg)
        leg_r = Rectangle(center=(6 mm + 25 mm * sin(10 deg), -48 mm - 25 mm * cos(10 deg)),
                          width=9 mm, height=50 mm, rotation=10 deg)
        hole shoulder { c = Circle(center=(0, -18 mm), diameter=3.2 mm) }
        drawing face {
            eye_l = Circle(center=(-4 mm, 2 mm), diameter=2 mm, fill=true)
            eye_r = Circle(center=(4 mm, 2 mm), diameter=2 mm, fill=true)
            smile = Arc(center=(0, 0), radius=5 mm, start_angle=220 deg, end_angle=320 deg)
        }
        Fixed(head)
        Fixed(torso)
        Fixed(shoulder)
        Fixed(face)
    }

    solid arms {
        bar = Slot(center=(0, 0), length=hands, width=12 mm)
        hand_l = Circle(center=(-hands / 2, 0), diameter=18 mm)
        hand_r = Circle(center=(hands / 2, 0), diameter=18 mm)
        hole pivot { c = Circle(center=(0, 0), diameter=3.2 mm) }
        hole strings {
            la = Circle(center=(-hands / 2, 4 mm), diameter=2.5 mm)
            lb = Circle(center=(-hands / 2, -4 mm), diameter=2.5 mm)
            ra = Circle(center=(hands / 2, 4 mm), diameter=2.5 mm)
            rb = Circle(center=(hands / 2, -4 mm), diameter=2.5 mm)
        }
        Fixed(bar)
        Fixed(pivot)
        Fixed(strings)
    }

    # flat layout
    RightOf(stick_r, stick_l, gap=5)
    AlignBottom(stick_r, stick_l)
    RightOf(crossbar, stick_r, gap=5)
    AlignBottom(crossbar, stick_r)
    Above(arms, crossbar, gap=5)
    AlignLeft(arms, crossbar)
    Above(body, arms, gap=5)
    AlignLeft(body, arms)

    # 3D: the uprights' faces look at each other along x; bar and acrobat face the front
    Place(stick_l, position=(-(inner / 2 + t), 0, 0), face="right", up="up")
    Place(stick_r, position=(inner / 2, 0, 0), face="right", up="up")
    Place(crossbar, position=(0, t / 2, 0), face="front", up="up")
    Place(arms, position=(0, t / 2, hang_z), face="front", up="up")
    Place(body, position=(0, -t / 2, hang_z + 18 mm), face="front", up="up")

    # the request's numbers
    assert stick_l.body.width == 20 mm and stick_l.body.height == 280 mm
    assert stick_l.body.bb.top - stick_l.string.a.center.y == 10 mm
    assert stick_l.body.bb.top - stick_l.string.b.center.y == 20 mm
    assert stick_l.mortise.slot[0].bb.center_y - stick_l.body.bb.bottom == 80 mm
    assert len(stick_l.mortise.slot) == 1
    assert crossbar.body.height == 16 mm
    assert crossbar.right_tenon.gap[0].bb.height > 0 mm
    assert hands == 80 mm and arms.hand_r.diameter == 18 mm and arms.bar.width == 12 mm
    assert arms.strings.ra.center.y - arms.strings.rb.center.y == 8 mm
    assert body.head.diameter == 22 mm
    assert distance(body.shoulder, body.head) >= 2 mm, "the dowel hole is in the torso"
    assert distance(arms.strings, arms.pivot) >= 30 mm
    # the arms bar (12 wide, length hands) with its round ends inside the hands
    assert arms.bar.length == hands
}
