# Request: a wall rack for four pairs of safety glasses in my workshop, cut from 6 mm ply.
# A back plate 320 x 160 mm with R6 corners, screwed to the wall by two countersunk M4
# screws (8.5 mm heads) 20 mm below its top edge and 140 mm either side of its middle.
# "SAFETY GLASSES" filled-engraved 14 mm high across it, "NO GLASSES, NO GRINDING" in 6 mm
# strokes under that. A shelf 320 x 70 (including its two 40 mm tenons, glued into mortises
# in the back) whose bottom face is 65 mm above the back's bottom edge; four U notches 30 mm
# wide and 45 mm deep open at its front edge, on a 64 mm pitch, centred, for the glasses'
# bridges. Two triangular brackets under the shelf at 140 mm either side of the middle, each
# arm 56 mm from the corner, with two 12 mm tenons into the back and two into the shelf.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

T = 6 mm            # ply
W = 320 mm          # back and shelf width
BH = 160 mm         # back height
SD = 70 mm          # shelf depth, tenons included
SHELF_Z = 65 mm     # shelf bottom face above the back's bottom edge
NOTCH_W = 30 mm
NOTCH_D = 45 mm
PITCH = 64 mm
BX = 140 mm         # bracket middle from the centre line
ARM = 56 mm         # bracket arm from the corner (tenon tips)

# bracket: corner at (0, 0) = the back's front face and the shelf's bottom face;
# tenon tips at x = -T (through the back) and y = +T (through the shelf)
def bracket() -> solid {
    body = Polygon([(-6, 6), (56, 6), (-6, -56)])
    top = tab_and_slot(part="tab", length=62 mm, thickness=6 mm, tabs=2, tab=12 mm, screw=0,
                       cx=25 mm, cy=6 mm)
    wall = tab_and_slot(part="tab", length=62 mm, thickness=6 mm, tabs=2, tab=12 mm, screw=0,
                        rotation=90 deg, cx=-6 mm, cy=-25 mm)
}

assembly rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=BH, corner_radius=6)
        # shelf mortises: the shelf's middle 6 mm plane at z = bottom + 65 + 3
        shelf_mortise = tab_and_slot(part="slot", length=W, thickness=T, tabs=2, tab=40 mm,
                                     screw=0, cx=0 mm, cy=-BH / 2 + SHELF_Z + T / 2)
        # bracket mortises: the brackets' tenon edge runs from z = shelf top down 62 mm
        left_mortise = tab_and_slot(part="slot", length=62 mm, thickness=T, tabs=2, tab=12 mm,
                                    screw=0, rotation=90 deg, cx=-BX,
                                    cy=-BH / 2 + SHELF_Z - 25 mm)
        right_mortise = tab_and_slot(part="slot", length=62 mm, thickness=T, tabs=2, tab=12 mm,
                                     screw=0, rotation=90 deg, cx=BX,
                                     cy=-BH / 2 + SHELF_Z - 25 mm)
        left_screw = clearance_hole(size=4, cx=-BX, cy=BH / 2 - 20 mm)
        right_screw = clearance_hole(size=4, cx=BX, cy=BH / 2 - 20 mm)
        Countersink([left_screw, right_screw], diameter=8.5 mm)
        drawing label {
            title = Text("SAFETY GLASSES", position=(0, 30), size=14, font="sans:Bold",
                         valign="middle", fill=true)
            rule = Text("NO GLASSES, NO GRINDING", position=(0, 8), size=6, valign="middle")
        }
        assert body.width == 320 mm and body.height == 160 mm, "back 320 x 160"
        assert right_screw.c.center.x - left_screw.c.center.x == 280 mm, "screws 140 either side"
        assert body.bb.top - left_screw.c.center.y == 20 mm, "screws 20 below the top"
        assert label.bb.bottom > body.bb.bottom + SHELF_Z + T, "label above the shelf"
    }

    solid shelf {
        body = Rectangle(center=(0, 0), width=W, height=SD)
        tenons = tab_and_slot(part="tab", length=W, thickness=T, tabs=2, tab=40 mm, screw=0,
                              cx=0 mm, cy=SD / 2)
        # bracket mortises: bracket corner (wall face) at shelf y = SD/2 - T
        left_mortise = tab_and_slot(part="slot", length=62 mm, thickness=T, tabs=2, tab=12 mm,
                                    screw=0, rotation=90 deg, cx=-BX, cy=SD / 2 - T - 25 mm)
        right_mortise = tab_and_slot(part="slot", length=62 mm, thickness=T, tabs=2, tab=12 mm,
                                     screw=0, rotation=90 deg, cx=BX, cy=SD / 2 - T - 25 mm)
        hole notches {
            for i in range(4) {
                s = Slot(start=((i - 1.5) * PITCH, -SD / 2 - 20 mm),
                         end=((i - 1.5) * PITCH, -SD / 2 + NOTCH_D - NOTCH_W / 2),
                         width=NOTCH_W, overrun=true)
            }
        }
        assert len(notches.s) == 4, "four notches"
        assert notches.s[1].center.x - notches.s[0].center.x == 64 mm, "64 mm pitch"
        assert notches.s[0].end.y + 15 mm - body.bb.bottom == 45 mm, "notches 45 deep"
        assert body.height == 70 mm, "shelf 70 deep with tenons"
    }

    left_bracket = bracket()
    right_bracket = bracket()

    Below(shelf, back, gap=10)
    AlignLeft(shelf, back)
    RightOf(left_bracket, shelf, gap=10)
    AlignTop(left_bracket, shelf)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignTop(right_bracket, left_bracket)

    # 3D: x right, y to the wall (back face of the back plate at y = 6), z up,
    # z = 0 at the back's middle
    Place(back, position=(0, 6, 0), face="front", up="up")
    Place(shelf, position=(0, 6 - SD / 2, -BH / 2 + SHELF_Z), face="up", up="back")
    Place(left_bracket, position=(-BX + 3, 0, -BH / 2 + SHELF_Z), face="left", up="up")
    Place(right_bracket, position=(BX + 3, 0, -BH / 2 + SHELF_Z), face="left", up="up")
}
