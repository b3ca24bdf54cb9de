# Request (pets): a wall dispenser for dog poo-bag rolls by the front door, from 3 mm ply.
# A back plate 90 x 170 mm with 10 mm rounded corners, screwed to the wall through two
# keyholes on its centre line (8 mm head, 4 mm slot 8 mm long, upward), the top one 55 mm
# above the plate's centre and the bottom one 72 mm below it. Two cheeks stand out from the
# back, 60 mm clear between them (a roll is 55 mm wide), each 60 mm deep and 70 mm tall with
# a fully rounded front, glued into the back with one 30 mm tenon; their middles are 40 mm
# above the plate's centre. Each cheek has an 8 mm hole for the dowel the roll turns on,
# 28 mm out from the back and halfway up. Under the cheeks "BAGS" is cut through in 14 mm bold
# stencil letters 15 mm below the plate's centre, and below that a paw print (a 16 x 13 mm
# pad and four toes 6 x 8 mm) is engraved filled, its pad 50 mm below the plate's centre.

units mm
thickness 3 mm

import "std/joints.aidl"
import "std/plates.aidl"

param gap = 60 mm, min = 40 mm, max = 90 mm
param cheek_depth = 60 mm, min = 45 mm, max = 80 mm
param cheek_h = 70 mm, min = 50 mm, max = 90 mm

t = 3 mm
cheek_x = gap / 2 + t / 2      # each cheek's middle from the centre line
cheek_y = 40 mm

def cheek() -> solid {
    body = RoundedRectangle(bottom_left=(0, -cheek_h / 2), width=cheek_depth, height=cheek_h,
                            corner_radii=[0, cheek_h / 2, cheek_h / 2, 0])
    hole axle {
        c = Circle(center=(28, 0), diameter=8)
    }
    tenon = tab_and_slot(part="tab", length=cheek_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                         rotation=90 deg, cx=0 mm, cy=0 mm)
    Fixed(body)
    Fixed(axle)
    assert axle.c.center.x - body.bb.left == 28 mm, "axle 28 mm out from the back"
    assert abs(axle.c.center.y - body.bb.center_y) < 0.001 mm, "axle halfway up"
}

assembly dispenser {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=90, height=170, corner_radius=10)
        top_screw = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, cx=0 mm, cy=55 mm)
        low_screw = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, cx=0 mm, cy=-72 mm)
        left_mortise = tab_and_slot(part="slot", length=cheek_h, thickness=t, tabs=1,
                                    tab=30 mm, screw=0, rotation=90 deg, cx=-cheek_x,
                                    cy=cheek_y)
        right_mortise = tab_and_slot(part="slot", length=cheek_h, thickness=t, tabs=1,
                                     tab=30 mm, screw=0, rotation=90 deg, cx=cheek_x,
                                     cy=cheek_y)
        hole word {
            w = Text("BAGS", position=(0, -15), size=14, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        drawing paw {
            pad = Ellipse(center=(0, -50), rx=8, ry=6.5, fill=true)
            toe1 = Ellipse(center=(-10, -39), rx=3, ry=4, rotation=20 deg, fill=true)
            toe2 = Ellipse(center=(-3.5, -35), rx=3, ry=4, fill=true)
            toe3 = Ellipse(center=(3.5, -35), rx=3, ry=4, fill=true)
            toe4 = Ellipse(center=(10, -39), rx=3, ry=4, rotation=-20 deg, fill=true)
        }
        Fixed(body)
        Fixed(top_screw)
        Fixed(low_screw)
        Fixed(word)
        Fixed(paw)
        assert body.bb.width == 90 mm and body.bb.height == 170 mm
        assert top_screw.head_hole.center.y - body.bb.center_y == 55 mm
        assert body.bb.center_y - low_screw.head_hole.center.y == 72 mm
        assert right_mortise.bb.left - left_mortise.bb.right == 60 mm, "60 mm between cheeks"
        assert body.bb.center_y - word.w.position.y == 15 mm
        assert body.bb.center_y - paw.pad.center.y == 50 mm
        assert paw.bb.bottom > low_screw.bb.top + 2 mm, "paw clear of the keyhole"
        assert word.bb.top < left_mortise.bb.bottom - 3 mm, "word under the cheeks"
    }
    left = cheek()
    right = cheek()

    # flat for cutting: cheeks beside the back
    RightOf(left, back, gap=6)
    RightOf(right, back, gap=6)
    AlignTop(left, back)
    Below(right, left, gap=6)

    # assembled: the back on the wall (z out of the wall), cheeks standing out of it
    Place(left, position=(-cheek_x + t / 2, cheek_y, 0), rotation=(0, -90 deg, 0))
    Place(right, position=(cheek_x + t / 2, cheek_y, 0), rotation=(0, -90 deg, 0))

    assert left.body.bb.width == 60 mm and left.body.bb.height == 70 mm
    assert left.axle.c.diameter == 8 mm
}
