# Request (electronics): a practice Morse straight key, 6 mm ply, five parts.
# - Base 140 x 70 mm, R8 corners. Two M4 holes for binding posts (the two wires) at
#   (-50, -22) and (-32, -22) from the base's centre; an M3 hole for the contact screw
#   at (40, 0); an M3 hole for the return-spring screw (a rubber band) at (-50, 0);
#   my call sign M0DXK engraved filled 8 mm tall, centred at (35, -24).
# - Two pivot cheeks 24 mm wide standing 26 mm above the base, round-topped (R12), an
#   M3 axle hole (fine fit) 14 mm above the base top; each glued into the base by one
#   16 mm tenon in a mortise. The cheeks' inner faces are 7 mm apart (the 6 mm lever
#   with 0.5 mm play each side); the axle is at x = -15.
# - The lever: 120 x 12 mm, its axle hole (M3, medium fit) 40 mm from its rear end, a
#   5 mm round notch in its bottom edge 4 mm from the rear end for the rubber band, and
#   a 10 x 6 mm tenon on top 10 mm from the front end.
# - The knob: a 30 mm disc with a mortise for the lever's tenon.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

t = 6 mm
base_w = 140 mm
base_d = 70 mm
axle_x = -15 mm
axle_h = 14 mm            # above the base top
cheek_w = 24 mm
cheek_h = 26 mm           # above the base top
tenon = 16 mm
play = 0.5 mm
lever_l = 120 mm
lever_h = 12 mm
lever_rear = 40 mm        # axle from the lever's rear end
knob_d = 30 mm
knob_from_front = 10 mm
cheek_y = t / 2 + play + t / 2      # cheek mid-plane from the lever's

def cheek() -> solid {
    # drawn with the base top on y = 0 and the axle on x = 0; tenon tips at y = -t
    post = Rectangle(bottom_left=(-cheek_w / 2, -t), width=cheek_w, height=cheek_h - cheek_w / 2 + t)
    crown = Circle(center=(0, cheek_h - cheek_w / 2), radius=cheek_w / 2)
    outline = Hull(post, crown)
    j = tab_and_slot(part="tab", length=cheek_w, thickness=t, tabs=1, tab=tenon, screw=0,
                     rotation=180 deg, cx=0 mm, cy=-t)
    axle = clearance_hole(size=3, fit="fine")
    Concentric(axle.c, crown)
}

assembly morse_key {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=base_w, height=base_d, corner_radius=8)
        post_a = clearance_hole(size=4, cx=-50 mm, cy=-22 mm)
        post_b = clearance_hole(size=4, cx=-32 mm, cy=-22 mm)
        contact = clearance_hole(size=3, cx=40 mm, cy=0 mm)
        spring = clearance_hole(size=3, cx=-50 mm, cy=0 mm)
        m_left = tab_and_slot(part="slot", length=cheek_w, thickness=t, tabs=1, tab=tenon,
                              screw=0, cx=axle_x, cy=cheek_y)
        m_right = tab_and_slot(part="slot", length=cheek_w, thickness=t, tabs=1, tab=tenon,
                               screw=0, cx=axle_x, cy=-cheek_y)
        drawing call {
            c = Text("M0DXK", position=(35, -24), size=8, font="sans:Bold", valign="middle",
                     fill=true)
        }
        Fixed(plate)
    }
    Place(base, position=(0, 0, 0), face="up")

    cheek_back = cheek()
    cheek_front = cheek()
    # drawings face front: the top face looks to -y, so a cheek spans y from position - t
    Place(cheek_back, position=(axle_x, cheek_y + t / 2, t), face="front", up="up")
    Place(cheek_front, position=(axle_x, -cheek_y + t / 2, t), face="front", up="up")

    solid lever {
        # drawn with the axle at (0, 0)
        bar = Rectangle(bottom_left=(-lever_rear, -lever_h / 2), width=lever_l, height=lever_h)
        stub = Rectangle(center=(lever_l - lever_rear - knob_from_front, lever_h / 2 + t / 2),
                         width=10, height=t)
        pivot = clearance_hole(size=3)
        hole band { n = Circle(center=(4 - lever_rear, -lever_h / 2), diameter=5) }
        Fixed(bar)
        pivot.c.center == (0, 0)
    }
    Place(lever, position=(axle_x, t / 2, t + axle_h), face="front", up="up")

    solid knob {
        disc = Circle(center=(0, 0), diameter=knob_d)
        hole mortise { m = Rectangle(center=(0, 0), width=10.2, height=t + 0.2) }
        Fixed(disc)
    }
    Place(knob, position=(axle_x + lever_l - lever_rear - knob_from_front, 0, t + axle_h + lever_h / 2),
          face="up")

    # flat layout for the sheet: the small parts to the right of the base
    RightOf(lever, base, gap=8)
    AlignTop(lever, base)
    Below(cheek_back, lever, gap=6)
    AlignLeft(cheek_back, lever)
    RightOf(cheek_front, cheek_back, gap=6)
    AlignTop(cheek_front, cheek_back)
    RightOf(knob, cheek_front, gap=6)
    AlignTop(knob, cheek_front)

    assert base.plate.bb.width == 140 mm and base.plate.bb.height == 70 mm, "base 140 x 70"
    assert lever.bar.bb.width == 120 mm and lever.bar.bb.height == 12 mm, "lever 120 x 12"
    assert lever.pivot.c.center.x - lever.bar.bb.left == 40 mm, "axle 40 mm from the rear"
    assert lever.bar.bb.right - lever.stub.center.x == 10 mm, "knob tenon 10 mm from the front"
    assert cheek_front.crown.center.y - 0 mm == 14 mm, "axle 14 mm above the base top"
    assert cheek_front.crown.bb.top == 26 mm, "cheek 26 mm tall"
    assert 2 * cheek_y - t == 7 mm, "cheeks' inner faces 7 mm apart"
    assert base.contact.c.center.x - base.plate.center.x == 40 mm, "contact screw at x 40"
    assert knob.disc.diameter == 30 mm, "30 mm knob"
    # the lever's bottom clears the base top by at least 6 mm at the contact screw
    assert axle_h - lever_h / 2 >= 6 mm, "room for the contact screw head"
}
