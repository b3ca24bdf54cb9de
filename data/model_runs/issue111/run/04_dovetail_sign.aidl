# "GAME ROOM" door sign, 200 x 60 mm when joined, cut as two 100 mm halves locked by a
# sliding dovetail along the 60 mm joint: 3 tails, 10 mm deep, 10 degrees, 0.1 mm
# clearance on the socket. The left half carries the tails (its body reaches 10 mm past the
# joint line), the right half the sockets. "GAME" engraved centered on the left half's
# 100 x 60 face, "ROOM" on the right half, 16 mm letters. Halves laid out 20 mm apart.

import "std/joints.aidl"

thickness 3 mm

assembly sign {
    solid left_half {
        body = Rectangle(bottom_left=(-100, -30), width=110, height=60)
        tails = dovetail(part="tail", length=60 mm, depth=10 mm, tails=3, angle=10 deg,
                         rotation=-90 deg, cx=0 mm, cy=0 mm)
        drawing word {
            t = Text("GAME", position=(-50, 0), size=16, valign="middle")
        }
    }
    solid right_half {
        body = Rectangle(bottom_left=(20, -30), width=100, height=60)
        sockets = dovetail(part="socket", length=60 mm, depth=10 mm, tails=3, angle=10 deg,
                           clearance=0.1 mm, rotation=-90 deg, cx=20 mm, cy=0 mm)
        drawing word {
            t = Text("ROOM", position=(70, 0), size=16, valign="middle")
        }
    }
    assert left_half.body.bb.width - 10 mm + right_half.body.bb.width == 200 mm, "200 mm joined"
    assert left_half.body.bb.height == 60 mm, "60 mm tall"
    assert left_half.word.bb.right < 0 mm - 5 mm, "GAME clear of the joint"
    assert right_half.word.bb.left > 30 mm + 5 mm, "ROOM clear of the sockets"
}
