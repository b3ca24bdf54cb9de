# Request (office): a stand that holds my phone flat above an A4 sheet to photograph documents.
# 6 mm ply, glued. Base 340 x 310 mm with the A4 sheet (297 x 210, landscape) marked by engraved
# corner marks 15 mm long, its front edge 5 mm behind the base's front edge, "A4" engraved inside
# its front right corner. An upright 50 x 320 mm stands 17 mm behind the sheet and holds a phone
# platform 120 x 90 mm on a 50 x 60 mm neck; the platform's underside 291 mm above the base's
# top (camera height), a 60 x 30 mm camera window right above the sheet's centre, "CAMERA"
# engraved beside it. Every joint two 15 mm glued tabs (the back brace into the upright: 3 tabs
# of 20 mm); a triangular gusset 56 x 56 mm under the neck, a back brace 66 deep x 126 tall.

import "std/joints.aidl"

thickness 6 mm

plane_y = 80 mm        # the upright's mid plane on the base (its faces at 77 and 83)
arm_z = 297 mm         # the platform's underside
a4_cy = -45 mm         # the A4 sheet's centre on the base
a4_w = 297 mm
a4_h = 210 mm
m = 15 mm              # corner mark length

assembly scanner {
    solid base {
        plate = Rectangle(center=(0, 0), width=340, height=310)
        upright_mortise = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                       screw=0, cx=0 mm, cy=plane_y)
        brace_mortise = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                     screw=0, rotation=90 deg, cx=0 mm, cy=113 mm)
        drawing a4 {
            l = -a4_w / 2
            r = a4_w / 2
            b = a4_cy - a4_h / 2
            tp = a4_cy + a4_h / 2
            tl = Polyline([(l, tp - m), (l, tp), (l + m, tp)])
            tr = Polyline([(r - m, tp), (r, tp), (r, tp - m)])
            br = Polyline([(r, b + m), (r, b), (r - m, b)])
            bl = Polyline([(l + m, b), (l, b), (l, b + m)])
            label = Text("A4", position=(r - 8, b + 6), size=8, anchor="end")
        }
    }

    solid upright {
        body = Rectangle(center=(0, 0), width=50, height=320)
        feet = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-160 mm)
        arm_mortise = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                   screw=0, cx=0 mm, cy=140 mm)
        gusset_mortise = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                      screw=0, rotation=90 deg, cx=0 mm, cy=112 mm)
        brace_mortise = tab_and_slot(part="slot", length=120 mm, thickness=6 mm, tabs=3, tab=20 mm,
                                     screw=0, rotation=90 deg, cx=0 mm, cy=-94 mm)
    }

    solid arm {
        neck = Rectangle(center=(0, -30), width=50, height=60)
        platform = Rectangle(center=(0, -105), width=120, height=90)
        tabs = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm, screw=0,
                            cx=0 mm, cy=0 mm)
        gusset_mortise = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                      screw=0, rotation=90 deg, cx=0 mm, cy=-31 mm)
        hole window { w = RoundedRectangle(center=(0, a4_cy - 83 mm), width=60, height=30,
                                           corner_radius=4) }
        drawing label {
            word = Text("CAMERA", position=(0, -92), size=6, valign="middle")
        }
    }

    solid gusset {
        tri = Polygon([(0, 0), (56, 0), (0, -56)])
        hole corner { r = Rectangle(center=(3, -3), width=8, height=8) }
        top_tabs = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                screw=0, cx=31 mm, cy=0 mm)
        side_tabs = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                 screw=0, rotation=90 deg, cx=0 mm, cy=-31 mm)
    }

    solid brace {
        tri = Polygon([(0, 0), (66, 0), (0, 126)])
        hole corner { r = Rectangle(center=(3, 3), width=8, height=8) }
        foot_tabs = tab_and_slot(part="tab", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                 screw=0, rotation=180 deg, cx=36 mm, cy=0 mm)
        side_tabs = tab_and_slot(part="tab", length=120 mm, thickness=6 mm, tabs=3, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=0 mm, cy=66 mm)
    }

    # on the sheet: the small parts right of the base
    RightOf(upright, base, gap=10)
    AlignTop(upright, base)
    RightOf(arm, upright, gap=10)
    AlignTop(arm, base)
    Below(gusset, arm, gap=10)
    AlignLeft(gusset, arm)
    RightOf(brace, gusset, gap=10)
    AlignTop(brace, gusset)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(upright, position=(0, plane_y + 3 mm, 160 mm), face="front", up="up")
    Place(arm, position=(0, plane_y + 3 mm, arm_z))
    Place(gusset, position=(3 mm, plane_y + 3 mm, arm_z + 6 mm), face="left", up="up")
    Place(brace, position=(-3 mm, plane_y - 3 mm, 0), face="right", up="up")

    # the request's numbers
    assert base.plate.bb.width == 340 mm and base.plate.bb.height == 310 mm, "base 340 x 310"
    assert base.a4.tr.points[1].x - base.a4.tl.points[1].x == 297 mm, "A4 297 wide"
    assert base.a4.tl.points[1].y - base.a4.bl.points[1].y == 210 mm, "A4 210 deep"
    assert base.a4.bl.points[1].y - base.plate.bb.bottom == 5 mm, "sheet 5 mm behind the front"
    assert base.upright_mortise.slot[0].bb.bottom - base.a4.tl.points[1].y == 17 mm, "upright 17 mm behind the sheet"
    assert upright.body.bb.width == 50 mm and upright.body.bb.height == 320 mm, "upright 50 x 320"
    assert arm.platform.bb.width == 120 mm and arm.platform.bb.height == 90 mm, "platform 120 x 90"
    assert arm.neck.bb.width == 50 mm and arm.neck.bb.height == 60 mm, "neck 50 x 60"
    assert arm_z - 6 mm == 291 mm, "platform 291 above the base's top"
    assert arm.window.w.bb.width == 60 mm and arm.window.w.bb.height == 30 mm, "window 60 x 30"
    # the window over the sheet's centre: arm y 0 is the upright's back face (plane_y + 3)
    assert arm.window.w.center.y + plane_y + 3 mm == a4_cy, "window over the sheet's centre"
    assert len(brace.side_tabs.gap) == 4, "3 tabs into the upright"
}
