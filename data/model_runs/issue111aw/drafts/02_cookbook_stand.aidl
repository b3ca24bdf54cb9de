# Request (kitchen): a cookbook stand from 6 mm ply, five parts glued with tab-and-slot joints.
# A back board 240 wide x 220 tall with 20 mm rounded top corners, leaning back at 75 degrees
# from the worktop, "RECIPES" engraved as serif bold letter outlines 20 mm tall near the top and
# "NONNA'S KITCHEN" engraved 7 mm under it. A ledge 240 wide x 60 deep for the book, square to
# the back, its rear edge tabbed (two 40 mm tabs) into the back 25 mm above the back's bottom edge.
# A page-holding lip standing 20 mm above the ledge, tabbed (two 40 mm tabs) into the ledge
# 51 mm out from the back. Two triangular brackets behind the back, 80 mm either side of the
# middle: each 110 mm long on the worktop and 170 mm along the back, tabbed into it with two
# 20 mm tabs. Show it assembled.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm            # ply
lean = 75 deg       # the back's angle from the worktop
ca = cos(lean)
sa = sin(lean)
back_w = 240 mm
back_h = 220 mm
ledge_y = 25 mm     # the ledge's middle plane above the back's bottom edge
ledge_d = 60 mm
lip_at = 51 mm      # the lip's middle plane out from the back's rear face
lip_h = 20 mm       # above the ledge
br_len = 170 mm     # along the back
br_foot = 110 mm    # on the worktop
br_x = 80 mm        # either side of the middle

# the bracket's tab tips lie on the back's front face; where that face meets the worktop
# (a point of the bracket's foot) sits this far up the back, in the back's own frame
br_start = -t * ca / sa

def bracket() -> solid {
    body = Polygon([(0, 0), (br_len * ca, br_len * sa), (br_foot, 0)])
    # the sloped edge (the tab tips) runs at `lean`; the panel lies to its right
    j = tab_and_slot(part="tab", length=br_len, thickness=t, tabs=2, tab=20, screw=0,
                     rotation=lean, cx=br_len * ca / 2, cy=br_len * sa / 2)
    # the tab gaps cut the top tip back to the shoulder line (t in from the tips): round the
    # corner where that line meets the back edge, and the foot's corner
    top = Point(br_len * ca + t / (br_foot * sa) * (br_foot - br_len * ca),
                br_len * sa - t / (br_foot * sa) * br_len * sa, construction=true)
    Fixed(top)
    # FIX after the first valid program: W0406, the piece of shoulder above the top tab leaves
    # room for a 4.09 mm round only
    Fillet(top, 4)
    Fillet(body.points[2], 6)
}

assembly stand {
    solid back {
        body = RoundedRectangle(bottom_left=(-back_w / 2, 0), width=back_w, height=back_h,
                                corner_radii=[20, 20, 0, 0])
        ledge_slots = tab_and_slot(part="slot", length=back_w, thickness=t, tabs=2, tab=40,
                                   screw=0, cx=0, cy=ledge_y)
        left_slots = tab_and_slot(part="slot", length=br_len, thickness=t, tabs=2, tab=20,
                                  screw=0, rotation=90 deg, cx=-br_x, cy=br_start + br_len / 2)
        right_slots = tab_and_slot(part="slot", length=br_len, thickness=t, tabs=2, tab=20,
                                   screw=0, rotation=90 deg, cx=br_x, cy=br_start + br_len / 2)
        drawing title {
            w = Text("RECIPES", position=(0, back_h - 30), size=20, font="serif:Bold",
                     valign="middle")
            s = Text("NONNA'S KITCHEN", position=(0, back_h - 55), size=7, valign="middle")
        }
    }

    solid ledge {
        body = Rectangle(bottom_left=(-back_w / 2, -ledge_d), width=back_w, height=ledge_d)
        j = tab_and_slot(part="tab", length=back_w, thickness=t, tabs=2, tab=40, screw=0,
                         cx=0, cy=0)
        lip_slots = tab_and_slot(part="slot", length=back_w, thickness=t, tabs=2, tab=40,
                                 screw=0, cx=0, cy=-lip_at)
    }

    solid lip {
        body = Rectangle(bottom_left=(-back_w / 2, 0), width=back_w, height=lip_h + t)
        j = tab_and_slot(part="tab", length=back_w, thickness=t, tabs=2, tab=40, screw=0,
                         rotation=180 deg, cx=0, cy=0)
    }

    for i in range(2) {
        brackets = bracket()
    }

    # flat on the sheet
    RightOf(ledge, back, gap=10)
    AlignTop(ledge, back)
    Below(lip, ledge, gap=10)
    AlignLeft(lip, ledge)
    Below(brackets[0], back, gap=10)
    AlignLeft(brackets[0], back)
    RightOf(brackets[1], brackets[0], gap=10)
    AlignBottom(brackets[1], brackets[0])

    # assembled: x across, y toward the back, z up
    Place(back, rotation=(lean, 0, 0), position=(0, 0, 0))
    Place(ledge, rotation=(lean - 90 deg, 0, 0), position=(0, (ledge_y - t / 2) * ca, (ledge_y - t / 2) * sa))
    Place(lip, rotation=(lean, 0, 0),
          position=(0, (ledge_y - t / 2) * ca - (lip_at - t / 2) * sa,
                    (ledge_y - t / 2) * sa + (lip_at - t / 2) * ca))
    Place(brackets[0], rotation=(90 deg, 0, 90 deg), position=(-br_x - t / 2, -t / sa, 0))
    Place(brackets[1], rotation=(90 deg, 0, 90 deg), position=(br_x - t / 2, -t / sa, 0))

    # the request's own numbers
    assert back.body.bb.width == 240 mm and back.body.bb.height == 220 mm, "back 240 x 220"
    assert ledge.body.bb.height == 60 mm, "ledge 60 deep"
    assert lip.body.bb.height - 6 mm == 20 mm, "lip stands 20 above the ledge"
    assert len(brackets) == 2, "two brackets"
    assert abs(brackets[0].body.points[2].x - brackets[0].body.points[0].x - 110 mm) < 0.01,
        "bracket foot 110 on the worktop"
    assert abs(back.right_slots.bb.center_x - back.left_slots.bb.center_x - 160 mm) < 0.01,
        "brackets 80 either side of the middle"
    assert back.title.bb.bottom > ledge_y + 100, "title above where the book hides it"
}
