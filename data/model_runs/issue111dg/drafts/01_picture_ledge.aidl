# Request (home): a picture ledge for the hallway, cut from 6 mm birch ply, glued together.
# 400 mm long. A back plate 400 x 100 hangs on two screws through keyholes (8 mm head,
# 4 mm shank, 10 mm slot upward) 300 mm apart, their heads 25 mm below the top edge.
# A shelf 60 mm deep (from the back plate's face to its front edge) goes into the back plate
# with three 30 mm tabs through closed slots, its underside 10 mm above the back plate's
# bottom edge. A front lip stands 25 mm above the shelf, 4 mm back from the shelf's front
# edge, with three 30 mm tabs through slots in the shelf. "MEMORIES" engraved filled on the
# lip's front, bold, 12 mm tall.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 6 mm

t = 6 mm
L = 400 mm
back_h = 100 mm
shelf_d = 60 mm
lip_h = 25 mm
shelf_z = 10 mm
lip_back = 4 mm

assembly ledge {
    solid back {
        body = Rectangle(center=(0, 0), width=L, height=back_h)
        # slots for the shelf's tabs: the shelf's middle stands shelf_z + t/2 above the bottom
        slots = tab_and_slot(part="slot", length=L, thickness=t, tabs=3, tab=30 mm, screw=0,
                             cx=0 mm, cy=-back_h / 2 + shelf_z + t / 2)
        k1 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=-150 mm, cy=back_h / 2 - 25 mm)
        k2 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=150 mm, cy=back_h / 2 - 25 mm)
    }

    solid shelf {
        # depth plus the tabs that pass through the back plate (back edge is +y)
        body = Rectangle(center=(0, 0), width=L, height=shelf_d + t)
        tabs = tab_and_slot(part="tab", length=L, thickness=t, tabs=3, tab=30 mm, screw=0,
                            cx=0 mm, cy=(shelf_d + t) / 2)
        # slots for the lip: its middle stands lip_back + t/2 from the front edge (-y)
        lip_slots = tab_and_slot(part="slot", length=L, thickness=t, tabs=3, tab=30 mm,
                                 screw=0, cx=0 mm, cy=-(shelf_d + t) / 2 + lip_back + t / 2)
    }

    solid lip {
        # height above the shelf plus the tabs through the shelf (bottom edge)
        body = Rectangle(center=(0, 0), width=L, height=lip_h + t)
        tabs = tab_and_slot(part="tab", length=L, thickness=t, tabs=3, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-(lip_h + t) / 2)
        drawing words {
            w = Text("MEMORIES", position=(0, 0), size=12, font="sans:Bold", fill=true,
                     valign="middle")
        }
        # centred on the part of the lip that shows above the shelf
        AlignCenterX(words, body)
        words.bb.center_y == body.bb.top - lip_h / 2
    }

    # flat on the sheet: one above the other
    Above(shelf, back, gap=10)
    Above(lip, shelf, gap=10)
    AlignCenterX(shelf, back)
    AlignCenterX(lip, back)

    # 3D: back face at y = 6 .. 0, shelf from the back plate forward, lip on the shelf
    Place(back, position=(0, t, back_h / 2), face="front", up="up")
    Place(shelf, position=(0, -(shelf_d + t) / 2 + t, shelf_z), face="up", up="back")
    Place(lip, position=(0, -(shelf_d + t) + lip_back + t + t, shelf_z + (lip_h + t) / 2),
          face="front", up="up")

    # the request's numbers
    assert back.body.bb.width == 400 mm, "400 mm long"
    assert back.k2.head_hole.center.x - back.k1.head_hole.center.x == 300 mm, "keyholes 300 apart"
    assert back.body.bb.top - back.k1.head_hole.center.y == 25 mm, "keyholes 25 below the top"
    assert shelf.body.bb.height - t == 60 mm, "shelf 60 deep in front of the back plate"
    assert lip.body.bb.height - t == 25 mm, "lip 25 above the shelf"
    assert len(shelf.tabs.gap) == 4, "three tabs: four gaps"
}
