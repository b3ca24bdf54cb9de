# Request (kitchen): a wall spice rack for six 45 mm spice jars, cut from 6 mm plywood,
# glued together, three parts:
# - back 300 x 160 mm, top corners R15; two keyholes to hang it (head 9 mm, shank 4.5 mm,
#   slot 10 mm long, upward), their head centres 30 mm below the top edge and 40 mm in from
#   the sides; three 30 mm mortises for the shelf, the shelf's underside 20 mm above the
#   back's bottom edge.
# - shelf 300 mm wide, 64 mm deep in front of the back, with three 30 mm tabs on its back
#   edge that go through the back (6 mm); two 40 mm mortises for the front rail, the rail's
#   front face 5 mm in from the shelf's front edge.
# - front rail 300 x 40 mm above the shelf, top corners R8, two 40 mm tabs on its bottom
#   edge into the shelf; "SPICES" engraved in serif, 16 mm high, centred on its face.

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/plates.aidl"

t = 6 mm
w = 300 mm
back_h = 160 mm
shelf_d = 64 mm
rail_h = 40 mm
shelf_up = 20 mm
rail_in = 5 mm

assembly spice_rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=w, height=back_h, corner_radii=[15, 15, 0, 0])
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                         cx=-w / 2 + 40 mm, cy=back_h / 2 - 30 mm)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                         cx=w / 2 - 40 mm, cy=back_h / 2 - 30 mm)
        # the shelf's middle (3 mm up from its underside) stands on this line
        mortise = tab_and_slot(part="slot", length=w, thickness=t, tabs=3, tab=30 mm, screw=0,
                               cx=0 mm, cy=-back_h / 2 + shelf_up + t / 2)
    }

    solid shelf {
        # drawn with its back edge up: depth in front of the back plus the tabs through it
        body = Rectangle(center=(0, 0), width=w, height=shelf_d + t)
        tabs = tab_and_slot(part="tab", length=w, thickness=t, tabs=3, tab=30 mm, screw=0,
                            cx=0 mm, cy=(shelf_d + t) / 2)
        # the rail's middle stands rail_in + t / 2 in from the front edge
        mortise = tab_and_slot(part="slot", length=w, thickness=t, tabs=2, tab=40 mm, screw=0,
                               cx=0 mm, cy=-(shelf_d + t) / 2 + rail_in + t / 2)
    }

    solid rail {
        # drawn upright: the face above the shelf plus the tabs into it
        body = RoundedRectangle(center=(0, 0), width=w, height=rail_h + t, corner_radii=[8, 8, 0, 0])
        tabs = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=40 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-(rail_h + t) / 2)
        drawing label {
            word = Text("SPICES", position=(0, -(rail_h + t) / 2 + t + rail_h / 2), size=16,
                        font="serif", valign="middle")
        }
    }

    Below(shelf, back, gap=10)
    Below(rail, shelf, gap=10)
    AlignCenterX(shelf, back)
    AlignCenterX(rail, back)

    # the request's numbers
    assert back.body.width == 300 mm and back.body.height == 160 mm, "back 300 x 160"
    assert back.body.bb.top - back.hang_l.head_hole.center.y == 30 mm, "keyholes 30 mm below the top"
    assert back.hang_l.head_hole.center.x - back.body.bb.left == 40 mm, "left keyhole 40 mm in"
    assert back.body.bb.right - back.hang_r.head_hole.center.x == 40 mm, "right keyhole 40 mm in"
    assert shelf.body.width == 300 mm and shelf.body.height == 64 mm + 6 mm, "shelf 300 x 64 + tabs"
    assert rail.body.width == 300 mm and rail.body.height == 40 mm + 6 mm, "rail 300 x 40 + tabs"
    assert rail.label.word.position.y - rail.body.bb.bottom == 6 mm + 20 mm, "label centred on the face"
}
