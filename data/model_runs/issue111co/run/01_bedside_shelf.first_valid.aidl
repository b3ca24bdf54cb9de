# Request: a clip-on bedside shelf for my kid's bunk bed, which has no room for a
# table. It hangs over the bed's 30 mm thick side rail on two hook brackets and
# needs no screws. Shelf 250 x 120 mm, its top 40 mm below the top of the rail;
# a 60 x 12 mm slot near the back for the phone charger cable; a front lip that
# stands 24 mm above the shelf with "SWEET DREAMS" engraved on it. Each bracket's
# hook has a 30 mm gap for the rail and a 50 mm tongue down the mattress side.
# 6 mm birch ply, everything glued with tabs in mortises. Bed 600 x 400 mm.

import "std/joints.aidl"

units mm
thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm
param rail = 30 mm, min = 18 mm, max = 45 mm     # bed rail thickness
param shelf_w = 250 mm, min = 180 mm, max = 400 mm
param shelf_d = 120 mm, min = 80 mm, max = 180 mm
param drop = 40 mm, min = 20 mm, max = 80 mm      # rail top to shelf top
param lip_h = 24 mm, min = 15 mm, max = 40 mm     # lip height above the shelf

upright_w = 20 mm
tongue = 50 mm
bracket_in = 25 mm          # bracket centre line from each shelf end
lip_in = 4 mm               # lip's back face from the shelf's front edge

# one hook bracket, drawn side-on: x away from the bed, y up; (0, 0) is the top
# of the rail at its outer face
def bracket() -> solid {
    tongue_bar = Rectangle(corner=(-rail - t, -tongue), opposite=(-rail, t))
    bridge = Rectangle(corner=(-rail - t, 0), opposite=(upright_w, t))
    upright = Rectangle(corner=(0, -drop - 120), opposite=(upright_w, t))
    # the arm the shelf sits on: its top edge is the shelf's top (the tabs' tips)
    arm = Polygon([(upright_w, -drop), (upright_w + shelf_d, -drop),
                   (upright_w + shelf_d, -drop - 16), (upright_w, -drop - 120)])
    tabs = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=20 mm,
                        screw=0, cx=upright_w + shelf_d / 2, cy=-drop)
    hole lighten {
        c = Circle(center=(upright_w + 40, -drop - 35), radius=15)
    }
}

assembly bedside_shelf {
    solid shelf {
        board = Rectangle(center=(0, 0), width=shelf_w, height=shelf_d)
        for s in [-1, 1] {
            bslots = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2,
                                  tab=20 mm, screw=0, rotation=90 deg,
                                  cx=s * (shelf_w / 2 - bracket_in), cy=0)
        }
        lslots = tab_and_slot(part="slot", length=shelf_w, thickness=t, tabs=3,
                              tab=30 mm, screw=0, cx=0,
                              cy=-shelf_d / 2 + lip_in + t / 2)
        hole cable {
            s = Slot(center=(shelf_w / 2 - bracket_in - 50, shelf_d / 2 - 18),
                     length=60, width=12)
        }
    }

    solid lip {
        body = Rectangle(center=(0, 0), width=shelf_w, height=lip_h + t)
        # tabs on the bottom edge, the lip above them
        ltabs = tab_and_slot(part="tab", length=shelf_w, thickness=t, tabs=3,
                             tab=30 mm, screw=0, rotation=180 deg,
                             cx=0, cy=-(lip_h + t) / 2)
        drawing words {
            w = Text("SWEET DREAMS", position=(0, t / 2), size=10, valign="middle")
        }
    }

    left = bracket()
    right = bracket()

    # flat on the sheet: brackets to the right of the shelf, lip under it
    RightOf(left, shelf, gap=8)
    AlignTop(left, shelf)
    RightOf(right, left, gap=8)
    AlignTop(right, left)
    Below(lip, shelf, gap=8)
    AlignLeft(lip, shelf)

    # assembled: rail's outer face at y = 0 (bed towards +y), rail top at z = 0
    Place(shelf, position=(0, -(upright_w + shelf_d / 2), -drop - t))
    Place(right, position=(shelf_w / 2 - bracket_in + t / 2, 0, 0), face="left", up="up")
    Place(left, position=(-(shelf_w / 2 - bracket_in) + t / 2, 0, 0), face="left", up="up")
    Place(lip, position=(0, -(upright_w + shelf_d - lip_in - t), -drop - t + (lip_h + t) / 2),
          face="front", up="up")

    # the request's numbers
    assert shelf.board.bb.width == 250 mm, "shelf 250 wide"
    assert shelf.board.bb.height == 120 mm, "shelf 120 deep"
    assert left.upright.bb.left - left.tongue_bar.bb.right == 30 mm, "hook gap fits the 30 mm rail"
    assert left.tongue_bar.bb.top - left.tongue_bar.bb.bottom - t == 50 mm, "50 mm tongue"
    assert left.bridge.bb.bottom - left.arm.bb.top == 40 mm, "shelf top 40 mm below the rail top"
    assert lip.body.bb.height - t == 24 mm, "lip stands 24 mm above the shelf"
    assert shelf.cable.s.length == 60 mm and shelf.cable.s.width == 12 mm, "cable slot 60 x 12"
    assert lip.bb.width <= 600 mm and left.bb.height <= 400 mm, "fits the bed"
}
