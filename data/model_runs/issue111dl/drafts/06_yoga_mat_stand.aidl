# Request (sport): a floor stand for three rolled yoga mats standing upright, 6 mm birch ply,
# finger-jointed at the corners (20 mm fingers). Two 180 x 600 sides, each with a 90 x 28 hand
# slot 60 mm below the top and "YOGA" cut through as a stencil, 50 mm letters reading upward,
# centred 230 mm up. A 480 x 180 top (outer width) with three 130 mm holes 150 mm apart for the
# mats, and a 480 x 180 bottom the mats stand on, with the three circles engraved under the
# holes. Sides' top and bottom edges carry the fingers; the plates' ends the slots.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
W = 480 mm
D = 180 mm
H = 600 mm
mat_d = 130 mm
pitch = 150 mm

def side_panel() -> solid {
    p = finger_panel(width=D, height=H, thickness=T, finger=20 mm, top="fingers",
                     bottom="fingers", left="flat", right="flat", cx=0, cy=H / 2)
    hole grip { s = Slot(center=(0, H - 60), length=90, width=28) }
    hole word {
        t = Text("YOGA", position=(0, 230), size=50, font="sans:Bold", rotation=90 deg,
                 valign="middle", stencil=true)
    }
    Rigid(self)
}

def plate() -> solid {
    p = finger_panel(width=W, height=D, thickness=T, finger=20 mm, left="slots",
                     right="slots", top="flat", bottom="flat")
    Rigid(self)
}

assembly stand {
    left = side_panel()
    right = side_panel()
    solid top {
        body = plate()
        hole mats {
            for i in range(3) { c = Circle(center=((i - 1) * pitch, 0), diameter=mat_d) }
        }
        Rigid(self)
    }
    solid bottom {
        body = plate()
        drawing rings {
            for i in range(3) { c = Circle(center=((i - 1) * pitch, 0), diameter=mat_d) }
        }
        Rigid(self)
    }

    # on the sheet
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(top, right, gap=10)
    AlignTop(top, left)
    Below(bottom, top, gap=10)
    AlignLeft(bottom, top)

    # in 3D: x across, y front to back, z up
    Place(left, position=(-W / 2 + T, 0, 0), face="left", up="up")
    Place(right, position=(W / 2 - T, 0, 0), face="right", up="up")
    Place(top, position=(0, 0, H - T), face="up")
    Place(bottom, position=(0, 0, 0), face="up")

    assert left.p.outline.width == 180 mm and left.p.outline.height == 600 mm, "sides 180 x 600"
    assert top.body.p.outline.width == 480 mm and top.body.p.outline.height == 180 mm, "top 480 x 180"
    assert len(top.mats.c) == 3, "three mats"
    assert top.mats.c[0].diameter == 130 mm, "130 mm holes"
    assert top.mats.c[1].center.x - top.mats.c[0].center.x == 150 mm, "150 apart"
    assert left.p.outline.bb.top - left.grip.s.center.y == 60 mm, "hand slot 60 below the top"
}
