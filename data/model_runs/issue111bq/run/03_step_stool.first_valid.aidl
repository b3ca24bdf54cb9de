# Request: a two-step stool so a child can reach the bathroom basin, 12 mm birch ply.
# Two stepped sides 300 mm deep: the lower tread's top 130 mm up (front half), the upper
# tread's top 240 mm up (back half), an arch 190 wide and 60 high under each side so it
# stands on two feet, and a 70 x 25 hand hole in each side under the upper step. The treads
# are 380 x 150 and overhang the sides; each side's step edges go up through them with two
# 40 mm tabs (flush with the tread's top). A riser (12 mm behind the upper step's nose) and a
# back panel (12 mm in from the back) brace the sides, 320 mm between them, with two 40 mm
# tabs through each side. All slots 0.1 mm clearance. The child's name "MIA" is engraved,
# filled bold 40 mm, on the riser's face above the lower tread.
units mm
thickness 12 mm
import "std/joints.aidl"

T = 12 mm
DEPTH = 300 mm
STEP1 = 130 mm        # lower tread top
STEP2 = 240 mm        # upper tread top
HALF = DEPTH / 2
IN_W = 320 mm         # between the sides
SIDE_X = IN_W / 2 + T / 2
TREAD_W = 380 mm
BRACE_LO = 72 mm      # the riser and back panel from 72 to 212 mm up
BRACE_H = 140 mm
RISER_AT = HALF + T + T / 2      # middle of the riser, from the front
BACK_AT = DEPTH - T - T / 2      # middle of the back panel
CL = 0.1 mm

def side() -> solid {
    # x: depth from the front, y: up; the step edges are the tabs' tips
    body = Polygon([(0, 0), (DEPTH, 0), (DEPTH, STEP2), (HALF, STEP2), (HALF, STEP1), (0, STEP1)])
    hole arch { a = RoundedRectangle(center=(HALF, 20), width=190, height=80, corner_radius=25) }
    hole hand { s = Slot(center=(225, 180), length=70, width=25) }
    low_tabs = tab_and_slot(part="tab", length=HALF, thickness=T, tabs=2, tab=40 mm, screw=0,
                            cx=HALF / 2, cy=STEP1)
    up_tabs = tab_and_slot(part="tab", length=HALF, thickness=T, tabs=2, tab=40 mm, screw=0,
                           cx=HALF + HALF / 2, cy=STEP2)
    riser_slots = tab_and_slot(part="slot", length=BRACE_H, thickness=T, tabs=2, tab=40 mm,
                               screw=0, clearance=CL, rotation=90 deg, cx=RISER_AT,
                               cy=BRACE_LO + BRACE_H / 2)
    back_slots = tab_and_slot(part="slot", length=BRACE_H, thickness=T, tabs=2, tab=40 mm,
                              screw=0, clearance=CL, rotation=90 deg, cx=BACK_AT,
                              cy=BRACE_LO + BRACE_H / 2)
}

def tread() -> solid {
    # x: across, y: depth (0 = its front edge)
    board = Rectangle(bottom_left=(-TREAD_W / 2, 0), width=TREAD_W, height=HALF)
    left = tab_and_slot(part="slot", length=HALF, thickness=T, tabs=2, tab=40 mm, screw=0,
                        clearance=CL, rotation=90 deg, cx=-SIDE_X, cy=HALF / 2)
    right = tab_and_slot(part="slot", length=HALF, thickness=T, tabs=2, tab=40 mm, screw=0,
                         clearance=CL, rotation=90 deg, cx=SIDE_X, cy=HALF / 2)
}

def brace() -> solid {
    # x: across, y: up from BRACE_LO; tab tips flush with the sides' outer faces
    board = Rectangle(bottom_left=(-IN_W / 2 - T, 0), width=IN_W + 2 * T, height=BRACE_H)
    left = tab_and_slot(part="tab", length=BRACE_H, thickness=T, tabs=2, tab=40 mm, screw=0,
                        rotation=90 deg, cx=-IN_W / 2 - T, cy=BRACE_H / 2)
    right = tab_and_slot(part="tab", length=BRACE_H, thickness=T, tabs=2, tab=40 mm, screw=0,
                         rotation=-90 deg, cx=IN_W / 2 + T, cy=BRACE_H / 2)
}

assembly step_stool {
    side_l = side()
    side_r = side()
    low = tread()
    up = tread()
    riser = brace()
    back = brace()
    drawing name {
        word = Text("MIA", position=(0, 98), size=40, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CutInto(name, riser)
    AlignCenterX(name, riser.board)
    name.word.position.y == riser.board.bb.bottom + 98 mm

    # on the sheet
    RightOf(side_r, side_l, gap=10)
    AlignBottom(side_r, side_l)
    Above(low, side_l, gap=10)
    AlignLeft(low, side_l)
    RightOf(up, low, gap=10)
    AlignBottom(up, low)
    Above(riser, low, gap=10)
    AlignLeft(riser, low)
    RightOf(back, riser, gap=10)
    AlignBottom(back, riser)

    # in 3D: x across, y depth (front at 0), z up
    Place(side_l, rotation=(90 deg, 0, 90 deg), position=(-SIDE_X - T / 2, 0, 0))
    Place(side_r, rotation=(90 deg, 0, 90 deg), position=(SIDE_X - T / 2, 0, 0))
    Place(low, position=(0, 0, STEP1 - T))
    Place(up, position=(0, HALF, STEP2 - T))
    Place(riser, rotation=(90 deg, 0, 0), position=(0, RISER_AT + T / 2, BRACE_LO))
    Place(back, rotation=(90 deg, 0, 0), position=(0, BACK_AT + T / 2, BRACE_LO))

    assert side_l.body.bb.width == 300 mm, "300 deep"
    assert side_l.body.bb.height == 240 mm, "upper tread top 240 up"
    assert side_l.low_tabs.bb.top - side_l.body.bb.bottom == 130 mm, "lower tread top 130 up"
    assert low.board.bb.width == 380 mm and low.board.bb.height == 150 mm, "treads 380 x 150"
    assert riser.board.bb.width - 2 * T == 320 mm, "320 between the sides"
    assert side_l.arch.a.bb.top - side_l.body.bb.bottom == 60 mm, "arch 60 high"
    assert side_l.hand.s.length == 70 mm and side_l.hand.s.width == 25 mm, "hand hole 70 x 25"
    assert name.word.size == 40 mm, "name 40 mm"
}
