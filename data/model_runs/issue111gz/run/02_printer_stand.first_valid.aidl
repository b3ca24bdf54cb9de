# Request (office): "A flat-pack stand that lifts my small inkjet printer off the desk, with a
# shelf under it for a ream of A4 paper. 6 mm plywood, glued tab-and-mortise joints, no screws.
# Top board 450 x 320 mm with a 60 mm cable hole centred 40 mm in from the back edge. Two side
# panels 320 deep and 160 tall overall; the side panels stand 15 mm in from the ends of the top
# (their centre lines), and their top edges carry 3 tabs 40 mm wide that go through mortises in
# the top. Each side has an arch cut out of its bottom edge (220 wide, 30 high) to leave two
# feet, and a hand hole 90 x 28 mm midway between the shelf and the top. The shelf is 300 deep,
# its top surface 60 mm above the desk, and runs between the sides with 2 tabs 60 mm wide on each
# end into mortises in the sides. A 50 mm half-round finger notch in the shelf's front edge to
# pull the paper out, and 'A4 PAPER' engraved behind the notch."

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
top_w = 450 mm
top_d = 320 mm
side_h = 160 mm
side_in = 15 mm          # side panel centre line in from the top's ends
shelf_d = 300 mm
shelf_up = 60 mm         # shelf top surface above the desk
side_x = top_w / 2 - side_in

def side_panel() -> solid {
    body = Rectangle(center=(0, side_h / 2), width=top_d, height=side_h)
    # tabs along the top edge, tips at the panel's top
    tabs = tab_and_slot(part="tab", length=top_d, thickness=t, tabs=3, tab=40 mm, screw=0,
                        cx=0 mm, cy=side_h)
    # mortises for the shelf: centred on the shelf's mid-plane
    shelf_mortise = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2, tab=60 mm,
                                 screw=0, cx=0 mm, cy=shelf_up - t / 2)
    hole feet {
        arch = Ellipse(center=(0, 0), rx=110, ry=30)
    }
    hole grip {
        s = Slot(center=(0, (shelf_up + side_h - t) / 2), length=90, width=28)
    }
    assert body.bb.height == 160 mm, "sides 160 tall overall"
    assert body.bb.width == 320 mm, "sides 320 deep"
    assert shelf_mortise.slot[0].bb.top - body.bb.bottom == 60 mm, "shelf top 60 above the desk"
    assert grip.bb.bottom - shelf_mortise.bb.top >= 10 mm, "hand hole clear of the shelf"
}

assembly printer_stand {
    solid top {
        board = Rectangle(center=(0, 0), width=top_w, height=top_d)
        left_mortise = tab_and_slot(part="slot", length=top_d, thickness=t, tabs=3, tab=40 mm,
                                    screw=0, rotation=90 deg, cx=-side_x, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=top_d, thickness=t, tabs=3, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=side_x, cy=0 mm)
        hole cable {
            c = Circle(center=(0, top_d / 2 - 40), diameter=60)
        }
        assert board.bb.width == 450 mm and board.bb.height == 320 mm, "top 450 x 320"
        assert board.bb.top - cable.c.center.y == 40 mm, "cable hole 40 in from the back"
        assert left_mortise.bb.center_x - board.bb.left == 15 mm, "sides 15 in from the ends"
    }

    left = side_panel()
    right = side_panel()

    solid shelf {
        # tab tip to tab tip: from one side's outer face to the other's
        board = Rectangle(center=(0, 0), width=2 * side_x + t, height=shelf_d)
        left_tabs = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=60 mm,
                                 screw=0, rotation=90 deg, cx=-(side_x + t / 2), cy=0 mm)
        right_tabs = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=60 mm,
                                  screw=0, rotation=270 deg, cx=side_x + t / 2, cy=0 mm)
        hole notch {
            c = Circle(center=(0, -shelf_d / 2), diameter=50)
        }
        drawing label {
            w = Text("A4 PAPER", position=(0, -shelf_d / 2 + 45), size=10, valign="middle")
        }
        assert board.bb.height == 300 mm, "shelf 300 deep"
        assert distance(label, notch) >= 5 mm, "label behind the notch"
    }

    Below(left, top, gap=10)
    AlignLeft(left, top)
    RightOf(right, left, gap=10)
    AlignTop(right, left)
    Below(shelf, left, gap=10)
    AlignLeft(shelf, top)
}
