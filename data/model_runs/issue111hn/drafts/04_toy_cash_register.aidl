# Request (toys): a toy cash register for my niece, in 3 mm ply, glued.
# - Two side cheeks, 140 deep, 110 tall at the back, 45 tall at the front, a straight
#   slope between; the back stays open (she keeps her play coins inside).
# - A keypad board, 120 wide between the cheeks (126 over its tabs) and 130 long, let into
#   the cheeks 5 mm below the slope on three 20 mm glued tabs each side.
# - A front board 44 tall, 120 between the cheeks, on two 12 mm tabs each side, its middle
#   8 mm behind the cheeks' front edge; "SHOP" engraved filled in bold (12 mm), and a
#   40 x 4 mm coin slot under it.
# - On the keypad: a 90 x 20 display with "£ 0.00", 12 keys 26 x 18 (3 mm corners) in 4 rows
#   of 3 on a 32 x 22 pitch: 7 8 9 / 4 5 6 / 1 2 3 / C 0 +, each label engraved in its key.

import "std/joints.aidl"

units mm
thickness 3 mm

D = 140 mm          # depth
H = 110 mm          # height at the back
HF = 45 mm          # height at the front
T = 3 mm
inset = 5 mm        # keypad's middle under the slope
slope_len = sqrt(D ** 2 + (H - HF) ** 2)
ux = D / slope_len
uy = -(H - HF) / slope_len
ang = atan2(-(H - HF), D)
kcx = D / 2 + inset * uy
kcy = (H + HF) / 2 - inset * ux
front_h = 44 mm
front_x = D - 8 mm
labels = ["7", "8", "9", "4", "5", "6", "1", "2", "3", "C", "0", "+"]

def cheek() -> solid {
    outline = Polygon([(0, 0), (D, 0), (D, HF), (0, H)])
    keys = tab_and_slot(part="slot", length=130 mm, thickness=T, tabs=3, tab=20 mm, screw=0,
                        rotation=ang, cx=kcx, cy=kcy)
    front = tab_and_slot(part="slot", length=front_h, thickness=T, tabs=2, tab=12 mm, screw=0,
                         rotation=90 deg, cx=front_x, cy=front_h / 2)
}

assembly register {
    left = cheek()
    right = cheek()

    solid keypad {
        body = Rectangle(center=(0, 0), width=126, height=130)
        lt = tab_and_slot(part="tab", length=130 mm, thickness=T, tabs=3, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-63 mm, cy=0 mm)
        rt = tab_and_slot(part="tab", length=130 mm, thickness=T, tabs=3, tab=20 mm, screw=0,
                          rotation=-90 deg, cx=63 mm, cy=0 mm)
        drawing face {
            display = RoundedRectangle(center=(0, 45), width=90, height=20, corner_radius=3)
            amount = Text("£ 0.00", position=(0, 45), size=10, font="sans", valign="middle")
            for i in range(12) {
                key = RoundedRectangle(center=(-32 + (i % 3) * 32, 15 - (i // 3) * 22),
                                       width=26, height=18, corner_radius=3)
                label = Text(labels[i], position=(-32 + (i % 3) * 32, 15 - (i // 3) * 22),
                             size=8, valign="middle")
            }
        }
    }

    solid front {
        body = Rectangle(center=(0, 0), width=126, height=front_h)
        lt = tab_and_slot(part="tab", length=front_h, thickness=T, tabs=2, tab=12 mm, screw=0,
                          rotation=90 deg, cx=-63 mm, cy=0 mm)
        rt = tab_and_slot(part="tab", length=front_h, thickness=T, tabs=2, tab=12 mm, screw=0,
                          rotation=-90 deg, cx=63 mm, cy=0 mm)
        hole coin { s = Rectangle(center=(0, -12), width=40, height=4) }
        drawing word {
            t = Text("SHOP", position=(0, 8), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    # laid out flat
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(keypad, right, gap=10)
    AlignBottom(keypad, right)
    Above(front, left, gap=10)
    AlignLeft(front, left)

    # assembled: cheeks upright (x = depth from the back, toward the front), keypad on its slope
    Place(left, face="left", up="up", position=(-60, 70, 0))
    Place(right, face="left", up="up", position=(63, 70, 0))
    Place(front, face="front", up="up", position=(0, 70 - front_x + T / 2, front_h / 2))
    # FIX after the first valid program: W0517 (0.532 mm collision of the keypad's tabs in
    # the cheeks' slots) was my sign slip: the keypad's bottom face lies T / 2 along the
    # inward normal (uy, -ux) from its middle, so its y is 70 - (kcx + T / 2 * uy)
    Place(keypad, rotation=(-ang, 0, 0),
          position=(0, 70 - (kcx + T / 2 * uy), kcy - T / 2 * ux))

    assert len(labels) == 12, "12 keys"
    assert len(keypad.face.key) == 12, "12 keys drawn"
    assert keypad.body.bb.width == 126 mm and keypad.body.bb.height == 130 mm, "keypad size"
    assert front.body.bb.height == 44 mm, "front 44 tall"
    assert left.outline.bb.width == 140 mm and left.outline.bb.height == 110 mm, "cheek 140 x 110"
    assert keypad.face.key[1].center.x - keypad.face.key[0].center.x == 32 mm, "32 mm pitch"
    assert keypad.face.key[0].center.y - keypad.face.key[3].center.y == 22 mm, "22 mm rows"
    assert keypad.face.bb.width <= 120 mm - 4 mm, "keys clear of the cheeks"
    assert keypad.face.bb.bottom >= keypad.body.bb.bottom + 3 mm, "keys on the board"
    assert keypad.face.bb.top <= keypad.body.bb.top - 3 mm, "display on the board"
    assert distance(front.coin, front.word) >= 3 mm, "coin slot clear of SHOP"
}
