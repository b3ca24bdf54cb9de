# Request (pets): a dog-poo-bag dispenser for the wall by the front door, in 4 mm ply.
# A back plate 90 x 200 mm with a keyhole (8 mm head) near the top, "DOG BAGS" engraved
# filled in 10 mm bold letters under it; a box for a bag roll 35 mm across and 60 mm long:
# two cheeks 50 mm deep x 70 mm tall, 64 mm apart inside, each with an 8.2 mm hole for the
# dowel the roll turns on, joined by two 15 mm tabs at the back into the back plate and two
# at the front into a front plate 84 x 70 mm; the front plate has a 50 x 8 mm slot near its
# bottom for the bag to come out and an engraved paw print above it. Under the box, a hook
# for the dog's lead stands 48 mm out from the back plate with two 10 mm tabs into it.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 4 mm

T = 4 mm
INNER = 64 mm       # between the cheeks
CHEEK_D = 50 mm
CHEEK_H = 70 mm
BOX_Y = 15 mm       # the box's middle on the back plate
HOOK_Y = -70 mm
ROLL_D = 35 mm

def cheek() -> solid {
    body = Rectangle(center=(0, 0), width=CHEEK_D, height=CHEEK_H)
    back_tabs = tab_and_slot(part="tab", length=CHEEK_H, thickness=T, tabs=2, tab=15,
                             screw=0, cx=-CHEEK_D / 2, cy=0, rotation=90 deg)
    front_tabs = tab_and_slot(part="tab", length=CHEEK_H, thickness=T, tabs=2, tab=15,
                              screw=0, cx=CHEEK_D / 2, cy=0, rotation=-90 deg)
    hole dowel { c = Circle(center=(0, 10), diameter=8.2) }
}

assembly poop_bag_dispenser {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=90, height=200, corner_radius=8)
        hang = keyhole(head=8 mm, cx=0, cy=80)
        box_l = tab_and_slot(part="slot", length=CHEEK_H, thickness=T, tabs=2, tab=15,
                             screw=0, cx=-(INNER / 2 + T / 2), cy=BOX_Y, rotation=90 deg)
        box_r = tab_and_slot(part="slot", length=CHEEK_H, thickness=T, tabs=2, tab=15,
                             screw=0, cx=INNER / 2 + T / 2, cy=BOX_Y, rotation=90 deg)
        hook_slots = tab_and_slot(part="slot", length=40, thickness=T, tabs=2, tab=10,
                                  screw=0, cx=0, cy=HOOK_Y, rotation=90 deg)
        drawing words {
            t = Text("DOG BAGS", (0, 57), size=10, font="sans:Bold", fill=true)
        }
    }
    cheek_l = cheek()
    cheek_r = cheek()
    solid front {
        plate = Rectangle(center=(0, 0), width=INNER + 2 * T + 12, height=CHEEK_H)
        left = tab_and_slot(part="slot", length=CHEEK_H, thickness=T, tabs=2, tab=15,
                            screw=0, cx=-(INNER / 2 + T / 2), cy=0, rotation=90 deg)
        right = tab_and_slot(part="slot", length=CHEEK_H, thickness=T, tabs=2, tab=15,
                             screw=0, cx=INNER / 2 + T / 2, cy=0, rotation=90 deg)
        hole exit { s = Slot(center=(0, -25), length=50, width=8) }
        drawing paw {
            pad = Ellipse(center=(0, 2), rx=10, ry=8, fill=true)
            toe1 = Circle(center=(-11, 12), radius=3.5, fill=true)
            toe2 = Circle(center=(-4, 17), radius=3.5, fill=true)
            toe3 = Circle(center=(4, 17), radius=3.5, fill=true)
            toe4 = Circle(center=(11, 12), radius=3.5, fill=true)
        }
    }
    solid hook {
        flange = Rectangle(corner=(0, -20), opposite=(10, 20))
        arm = Stroke(Polyline([(5, -14), (40, -14), (48, 0)]), width=10)
        tabs = tab_and_slot(part="tab", length=40, thickness=T, tabs=2, tab=10, screw=0,
                            cx=0, cy=0, rotation=90 deg)
    }

    back.bb.center == (0, 0)
    cheek_l.bb.center == (90, 60)
    cheek_r.bb.center == (90, -30)
    front.bb.center == (180, 60)
    hook.bb.center == (170, -40)

    # in 3D: the wall is y = 0, the front is -y
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(cheek_l, position=(-(INNER / 2), -CHEEK_D / 2, BOX_Y), face="left", up="up")
    Place(cheek_r, position=(INNER / 2, -CHEEK_D / 2, BOX_Y), face="right", up="up")
    Place(front, position=(0, -(CHEEK_D - T), BOX_Y), face="front", up="up")
    Place(hook, position=(T / 2, 0, HOOK_Y), face="left", up="up")

    assert back.plate.width == 90 mm and back.plate.height == 200 mm, "back 90 x 200"
    assert cheek_l.body.width == 50 mm and cheek_l.body.height == 70 mm, "cheek 50 x 70"
    assert back.box_r.slot[0].center.x - back.box_l.slot[0].center.x == 64 mm + T,
        "cheeks 64 apart inside"
    assert front.plate.width == 84 mm and front.plate.height == 70 mm, "front 84 x 70"
    assert cheek_l.dowel.c.diameter == 8.2 mm, "8.2 mm dowel hole"
    # the roll turns clear of the back plate and the front plate
    assert cheek_l.dowel.c.center.x - ROLL_D / 2 - cheek_l.back_tabs.gap[0].bb.right >= 2 mm,
        "roll clear of the back"
    assert cheek_l.front_tabs.gap[0].bb.left - (cheek_l.dowel.c.center.x + ROLL_D / 2) >= 2 mm,
        "roll clear of the front"
    assert front.exit.s.length == 50 mm and front.exit.s.width == 8 mm, "exit 50 x 8"
    assert distance(front.paw, front.exit) >= 3 mm, "paw above the exit slot"
    assert distance(front.exit, front.left) >= 3 mm, "exit clear of the mortises"
    assert hook.arm.bb.right - hook.flange.bb.left == 48 mm + 5 mm, "hook 48 out"
    assert back.hang.head_hole.diameter == 8 mm, "8 mm keyhole"
    assert back.words.t.bb.top <= back.hang.bb.bottom - 3 mm, "words under the keyhole"
    assert back.words.t.bb.bottom >= back.box_l.bb.top + 3 mm, "words above the box"
    assert back.hook_slots.bb.top <= back.box_l.bb.bottom - 10 mm, "hook under the box"
}
