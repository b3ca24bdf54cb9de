# Request: a cradle that hangs a mini PC (an Intel NUC, 117 x 112 x 51 mm) on the back of
# a monitor, in 6 mm birch ply. A back plate 160 mm wide goes between the monitor and the
# monitor arm: four 4.5 mm (M4 clearance) holes on the VESA 100 square and four on the
# VESA 75 square, both centred 70 mm below the plate's top edge; corners R8. Below the
# arm's 120 mm plate the PC stands with its 117 x 112 face against the back plate, on a
# shelf 147 mm wide, between two cheeks 100 mm tall that leave 119 mm between them, and
# is kept from falling forward by a strap 147 x 30 mm, 52 mm in front of the plate (PC
# 51 + 1 mm). The top of the PC space is 10 mm below the arm's plate (70 mm below the
# VESA centre). Each cheek has a 32 x 70 mm R5 window for the ports. The parts are glued
# with tabs in closed slots (2 tabs along the long edges, 1 along the short ones). The
# strap is engraved "MINI PC".

import "std/joints.aidl"
import "std/fasteners.aidl"

t = 6 mm
thickness t

PC_W = 117 mm
PC_H = 112 mm
PC_D = 51 mm
GAP = 1 mm
IN_W = PC_W + 2 * GAP          # 119 between the cheeks
DEPTH = PC_D + GAP             # 52 from plate to strap
CHEEK_H = 100 mm
SHELF_W = 147 mm
STRAP_H = 30 mm
CX = IN_W / 2 + t / 2          # cheek centre line, 62.5
PC_TOP = -70 mm                # y of the PC space's top on the plate (VESA centre at 0)
SHELF_Y = PC_TOP - (PC_H + GAP)   # top face of the shelf, -183

def plate() -> solid {
    body = RoundedRectangle(corner=(-80, 70), opposite=(80, SHELF_Y - t - 10),
                            corner_radius=8)
    hole vesa100 {
        for p in [(-50, -50), (50, -50), (50, 50), (-50, 50)] {
            c = Circle(center=p, diameter=4.5)
        }
    }
    hole vesa75 {
        for p in [(-37.5, -37.5), (37.5, -37.5), (37.5, 37.5), (-37.5, 37.5)] {
            c = Circle(center=p, diameter=4.5)
        }
    }
    shelf_slots = tab_and_slot(part="slot", length=SHELF_W, thickness=t, tabs=2, tab=30,
                               screw=0, cx=0, cy=SHELF_Y - t / 2)
    left_slots = tab_and_slot(part="slot", length=CHEEK_H, thickness=t, tabs=2, tab=20,
                              screw=0, rotation=90, cx=-CX, cy=SHELF_Y + CHEEK_H / 2)
    right_slots = tab_and_slot(part="slot", length=CHEEK_H, thickness=t, tabs=2, tab=20,
                               screw=0, rotation=90, cx=CX, cy=SHELF_Y + CHEEK_H / 2)
}

# the shelf: y = 0 is the plate's front face, the PC space toward -y; tabs into the plate
def shelf() -> solid {
    body = Rectangle(corner=(-SHELF_W / 2, -(DEPTH + t)), opposite=(SHELF_W / 2, t))
    back = tab_and_slot(part="tab", length=SHELF_W, thickness=t, tabs=2, tab=30, screw=0,
                        cx=0, cy=t)
    left_slot = tab_and_slot(part="slot", length=DEPTH, thickness=t, tabs=1, tab=30,
                             screw=0, rotation=90, cx=-CX, cy=-DEPTH / 2)
    right_slot = tab_and_slot(part="slot", length=DEPTH, thickness=t, tabs=1, tab=30,
                              screw=0, rotation=90, cx=CX, cy=-DEPTH / 2)
}

# a cheek: x = depth from the plate's face, y = height above the shelf
def cheek() -> solid {
    core = Rectangle(corner=(0, 0), opposite=(DEPTH, CHEEK_H))
    back_strip = Rectangle(corner=(-t, 0), opposite=(0, CHEEK_H))
    bottom_strip = Rectangle(corner=(0, -t), opposite=(DEPTH, 0))
    front_strip = Rectangle(corner=(DEPTH, 0), opposite=(DEPTH + t, STRAP_H))
    back = tab_and_slot(part="tab", length=CHEEK_H, thickness=t, tabs=2, tab=20, screw=0,
                        rotation=90, cx=-t, cy=CHEEK_H / 2)
    bottom = tab_and_slot(part="tab", length=DEPTH, thickness=t, tabs=1, tab=30, screw=0,
                          rotation=180, cx=DEPTH / 2, cy=-t)
    front = tab_and_slot(part="tab", length=STRAP_H, thickness=t, tabs=1, tab=15, screw=0,
                         rotation=-90, cx=DEPTH + t, cy=STRAP_H / 2)
    hole window {
        w = RoundedRectangle(center=(DEPTH / 2, CHEEK_H / 2), width=32, height=70,
                             corner_radius=5)
    }
}

def strap() -> solid {
    body = Rectangle(corner=(-SHELF_W / 2, 0), opposite=(SHELF_W / 2, STRAP_H))
    left_slot = tab_and_slot(part="slot", length=STRAP_H, thickness=t, tabs=1, tab=15,
                             screw=0, rotation=90, cx=-CX, cy=STRAP_H / 2)
    right_slot = tab_and_slot(part="slot", length=STRAP_H, thickness=t, tabs=1, tab=15,
                              screw=0, rotation=90, cx=CX, cy=STRAP_H / 2)
    drawing label {
        word = Text("MINI PC", position=(0, STRAP_H / 2), size=10, valign="middle")
    }
}

assembly cradle {
    back_plate = plate()
    floor = shelf()
    left = cheek()
    right = cheek()
    front = strap()

    # flat on the sheet
    RightOf(floor, back_plate, gap=10)
    AlignTop(floor, back_plate)
    Below(left, floor, gap=10)
    AlignLeft(left, floor)
    RightOf(right, left, gap=10)
    AlignTop(right, left)
    Below(front, left, gap=10)
    AlignLeft(front, floor)

    # in 3D: the plate upright, its front face at y = -t; the PC space in front of it
    Place(back_plate, position=(0, 0, 0), face="front", up="up")
    Place(floor, position=(0, -t, SHELF_Y - t), face="up")
    Place(left, position=(-CX + t / 2, -t, SHELF_Y), face="left", up="up")
    Place(right, position=(CX + t / 2, -t, SHELF_Y), face="left", up="up")
    Place(front, position=(0, -t - DEPTH, SHELF_Y), face="front", up="up")

    assert distance(back_plate.vesa100.c[0].center, back_plate.vesa100.c[1].center) == 100 mm,
        "VESA 100"
    assert distance(back_plate.vesa75.c[0].center, back_plate.vesa75.c[1].center) == 75 mm,
        "VESA 75"
    assert back_plate.body.bb.top - back_plate.vesa100.bb.center_y == 70 mm,
        "VESA centre 70 below the top"
    assert back_plate.body.bb.width == 160 mm, "plate 160 wide"
    assert back_plate.vesa100.c[0].diameter == 4.5 mm, "M4 clearance"
    assert 2 * CX - t == 119 mm, "119 between the cheeks"
    assert DEPTH == 52 mm, "strap 52 in front of the plate"
    assert floor.body.bb.width == 147 mm, "shelf 147 wide"
    assert front.body.bb.width == 147 mm and front.body.bb.height == 30 mm, "strap 147 x 30"
    assert left.core.bb.height == 100 mm, "cheeks 100 tall"
    assert PC_TOP == -70 mm, "PC space 70 below the VESA centre"
    assert left.window.w.width == 32 mm and left.window.w.height == 70 mm, "port window"
}
