# Request (home): a boot jack for the back door, cut from 9 mm birch ply. A 300 x 90 mm board
# with 10 mm rounded corners; at the front end a U-shaped heel notch 50 mm wide and 80 mm deep
# (round bottom, its mouth corners rounded 5 mm) to catch the boot heel. Under it a riser
# 90 mm wide, standing square to the board with its middle 110 mm from the heel end, glued
# into the board by two 20 mm tabs through two mortises; the board tilts 12 degrees with its
# back end on the floor, so the riser's length is whatever makes its foot reach the floor
# (about 40 mm), and an arch 50 mm wide and 12 mm high is cut out of the riser's foot so it
# stands on two feet. A 10 mm hanging hole 15 mm from the back end and "BOOT JACK" engraved
# 12 mm tall on the standing half.

import "std/joints.aidl"

thickness 9 mm

T = 9 mm                      # the ply
param tilt = 12 deg, min = 8 deg, max = 18 deg
L_BOARD = 300 mm
W_BOARD = 90 mm
XR = L_BOARD / 2 - 110 mm     # riser's middle, from the board's centre
RISER = (XR + L_BOARD / 2) * tan(tilt)   # riser length below the board, at its middle
Z0 = L_BOARD / 2 * sin(tilt)  # board centre's height: back end's bottom on the floor

assembly boot_jack {
    solid board {
        deck = RoundedRectangle(center=(0, 0), width=L_BOARD, height=W_BOARD, corner_radius=10)
        hole heel {
            s = Slot(start=(L_BOARD / 2 - 80 mm + 25 mm, 0), end=(L_BOARD / 2 + 30 mm, 0), width=50,
                     overrun=true)
        }
        Fillet([deck, heel.s], 5)
        hole hang {
            c = Circle(center=(-L_BOARD / 2 + 15 mm, 0), diameter=10)
        }
        seat = tab_and_slot(part="slot", length=W_BOARD, thickness=T, tabs=2, tab=20 mm,
                            screw=0, rotation=90 deg, cx=XR, cy=0 mm)
        drawing label {
            t = Text("BOOT JACK", position=(-50, 0), size=12, valign="middle")
        }
    }

    solid riser {
        body = Rectangle(bottom_left=(-W_BOARD / 2, -RISER), width=W_BOARD, height=RISER + T)
        hole arch {
            e = Ellipse(center=(0, -RISER), rx=25, ry=12)
        }
        tabs = tab_and_slot(part="tab", length=W_BOARD, thickness=T, tabs=2, tab=20 mm,
                            screw=0, cx=0 mm, cy=T)
    }

    # flat on the sheet: riser below the board
    Below(riser, board, gap=10)
    AlignCenterX(riser, board)

    # in 3D: board tilted heel-end up, riser square to it under the mortises
    Place(board, position=(0, 0, Z0), rotation=(0, -tilt, 0))
    Place(riser, position=((XR - T / 2) * cos(tilt), 0, (XR - T / 2) * sin(tilt) + Z0),
          rotation=(90 deg - tilt, 0, 90 deg))

    # the request's numbers
    assert board.deck.width == 300 mm and board.deck.height == 90 mm, "board 300 x 90"
    assert board.heel.s.width == 50 mm, "heel notch 50 wide"
    assert board.deck.bb.right - board.heel.s.bb.left == 80 mm, "heel notch 80 deep"
    assert board.deck.bb.right - board.seat.slot[0].bb.center_x == 110 mm, "riser 110 from heel end"
    assert len(board.seat.slot) == 2, "two mortises"
    assert riser.body.width == 90 mm, "riser 90 wide"
    assert RISER > 35 mm and RISER < 45 mm, "riser about 40 mm"
    assert board.hang.c.center.x - board.deck.bb.left == 15 mm, "hanging hole 15 from back end"
}
