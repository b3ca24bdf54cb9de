# Request (home): a slip-over cover for a 600 mm wide, 560 mm tall radiator, cut from 6 mm MDF.
# Front panel 700 mm wide x 600 mm tall (top tabs included), with a staggered grid of
# 8 rows x 10 columns of 30 mm round vent holes (54 mm apart across, 46 mm between rows) and
# a shallow arched opening at the foot (500 mm wide, 40 mm high) for air to come in.
# Two side panels 150 mm deep x 600 mm tall, finger-jointed to the front's vertical edges
# (40 mm fingers). A 740 x 170 mm top shelf overhanging 20 mm at the front and both sides,
# glued on: three 60 mm tabs on the front's top edge and one 60 mm tab on each side's top edge
# go into matching mortises in the shelf.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm
param front_w = 700 mm, min = 500 mm, max = 900 mm
param cover_h = 600 mm, min = 400 mm, max = 800 mm
param depth = 150 mm, min = 100 mm, max = 200 mm
param overhang = 20 mm, min = 10 mm, max = 40 mm
param finger = 40 mm, min = 20 mm, max = 60 mm

def side_panel() -> solid {
    body = Rectangle(center=(0, 0), width=depth, height=cover_h)
    # the front edge (x = -depth/2) mates the front panel's fingers
    fingers = finger_edge(length=cover_h, thickness=t, finger=finger, start="gap",
                          rotation=90 deg, cx=-depth / 2, cy=0 mm)
    # one tab on the top edge into the shelf
    top_tab = tab_and_slot(part="tab", length=depth, thickness=t, tabs=1, tab=60 mm, screw=0,
                           cx=0 mm, cy=cover_h / 2)
}

assembly radiator_cover {
    solid front {
        body = Rectangle(center=(0, 0), width=front_w, height=cover_h)
        left_fingers = finger_edge(length=cover_h, thickness=t, finger=finger, start="tab",
                                   rotation=90 deg, cx=-front_w / 2, cy=0 mm)
        right_fingers = finger_edge(length=cover_h, thickness=t, finger=finger, start="tab",
                                    rotation=-90 deg, cx=front_w / 2, cy=0 mm)
        top_tabs = tab_and_slot(part="tab", length=front_w, thickness=t, tabs=3, tab=60 mm,
                                screw=0, cx=0 mm, cy=cover_h / 2)
        # FIX after the first valid program: the grid was 15 mm right of centre (first centre
        # written as -241.5 instead of -(9 x 54 + 27) / 2 = -256.5: 93.5 mm margin left, 63.5 right)
        hole vent { c = Circle(center=(-(9 * 54 + 27) / 2, -191), diameter=30) }
        vents = GridPattern(vent, 8, 10, (54, 46), stagger=true)
        hole foot_arch { e = Ellipse(center=(0, -cover_h / 2), rx=250, ry=40) }
        AlignCenterX(foot_arch, body)
    }

    solid shelf {
        board = Rectangle(center=(0, 0), width=front_w + 2 * overhang, height=depth + overhang)
        # mortises where the front panel's middle stands: overhang + t/2 behind the front edge
        front_slots = tab_and_slot(part="slot", length=front_w, thickness=t, tabs=3, tab=60 mm,
                                   screw=0, cx=0 mm, cy=-(depth + overhang) / 2 + overhang + t / 2)
        # mortises for the sides: their middles t/2 inside the front's outer width
        left_slot = tab_and_slot(part="slot", length=depth, thickness=t, tabs=1, tab=60 mm,
                                 screw=0, rotation=90 deg, cx=-front_w / 2 + t / 2,
                                 cy=-(depth + overhang) / 2 + overhang + depth / 2)
        right_slot = tab_and_slot(part="slot", length=depth, thickness=t, tabs=1, tab=60 mm,
                                  screw=0, rotation=90 deg, cx=front_w / 2 - t / 2,
                                  cy=-(depth + overhang) / 2 + overhang + depth / 2)
    }

    left_side = side_panel()
    right_side = side_panel()

    # flat on the sheet: front, then the two sides to its right, the shelf above
    RightOf(left_side, front, gap=10)
    RightOf(right_side, left_side, gap=10)
    AlignBottom(left_side, front)
    AlignBottom(right_side, front)
    Above(shelf, front, gap=10)
    AlignLeft(shelf, front)

    # assembled: the front's outer face `overhang` behind the shelf's front edge
    Place(front, position=(0, -(depth + overhang) / 2 + overhang + t, cover_h / 2),
          face="front", up="up")
    Place(left_side, position=(-front_w / 2, -(depth + overhang) / 2 + overhang + depth / 2,
          cover_h / 2), face="right", up="up")
    Place(right_side, position=(front_w / 2 - t, -(depth + overhang) / 2 + overhang + depth / 2,
          cover_h / 2), face="right", up="up")
    Place(shelf, position=(0, 0, cover_h - t), face="up")

    # the request's own numbers
    assert front.body.bb.width == 700 mm and front.body.bb.height == 600 mm
    assert left_side.body.bb.width == 150 mm and left_side.body.bb.height == 600 mm
    assert shelf.board.bb.width == 740 mm and shelf.board.bb.height == 170 mm
    assert len(front.vents) == 80, "8 rows x 10 columns of vents"
    assert front.vents[1].c.center.x - front.vents[0].c.center.x == 54 mm
    assert front.vents[10].c.center.y - front.vents[0].c.center.y == 46 mm
    assert front.vent.c.diameter == 30 mm
    assert front.foot_arch.e.bb.width == 500 mm
    # vents keep at least 40 mm of board round them and clear the foot arch
    assert front.vents[0].c.bb.left - front.body.bb.left >= 40 mm
    assert front.body.bb.right - front.vents[79].c.bb.right >= 40 mm
    assert front.body.bb.top - front.vents[79].c.bb.top >= 40 mm
    assert front.vents[0].c.bb.bottom - front.foot_arch.e.bb.top >= 20 mm
    # FIX after the first valid program: the grid is centred across the panel
    assert abs((front.vents[0].c.bb.left - front.body.bb.left) -
               (front.body.bb.right - front.vents[79].c.bb.right)) < 0.01 mm, "vents centred"
}
