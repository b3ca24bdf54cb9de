# Request (kitchen): a shortbread cookie stamp from 3 mm cast acrylic. The stamp face is a
# 60 mm disc, engraved deep (filled) with "MERCI" in bold letters, mirrored so that the
# cookie reads right, at most 44 mm wide, above a 12 mm tall heart, and a 2 mm wide border
# ring 1 mm in from the rim. A plain 60 mm back disc is glued behind the face. The handle is
# two 36 x 30 mm fins with rounded tops (r 10), cross-halved (15 mm slot in each), each glued
# into the back disc by two 8 mm tabs in mortises.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
D = 60 mm
fin_w = 36 mm
fin_h = 30 mm

def fin(from_top=true) -> solid {
    plate = RoundedRectangle(bottom_left=(-fin_w / 2, 0), width=fin_w, height=fin_h,
                             corner_radii=[10 mm, 10 mm, 0, 0])
    if from_top {
        halving = cross_halving(depth=fin_h / 2, thickness=T, cx=0, cy=fin_h)
    } else {
        halving = cross_halving(depth=fin_h / 2, thickness=T, rotation=180 deg, cx=0, cy=0)
    }
    tabs = tab_and_slot(part="tab", length=fin_w, thickness=T, tabs=2, tab=8 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
}

assembly stamp {
    solid face {
        disc = Circle(center=(0, 0), diameter=D)
        axis = Line((0, -30), (0, 30), construction=true)
        drawing label {
            word = Text("MERCI", position=(0, 6), size=14, font="sans:Bold", valign="middle",
                        max_width=44 mm, fill=true)
        }
        Flip(label, about=axis)
        drawing heart {
            l = Hull(Circle(center=(-3, -11), radius=3), Point(0, -20), fill=true)
            r = Hull(Circle(center=(3, -11), radius=3), Point(0, -20), fill=true)
        }
        drawing border {
            ring = Shell(Circle(center=(0, 0), radius=D / 2 - 3 mm), 2 mm, fill=true)
        }
    }
    solid back {
        disc = Circle(center=(0, 0), diameter=D)
        along_x = tab_and_slot(part="slot", length=fin_w, thickness=T, tabs=2, tab=8 mm, screw=0,
                               cx=0, cy=0)
        along_y = tab_and_slot(part="slot", length=fin_w, thickness=T, tabs=2, tab=8 mm, screw=0,
                               rotation=90 deg, cx=0, cy=0)
    }
    fin_a = fin(from_top=true)
    fin_b = fin(from_top=false)

    # flat on the sheet
    face.disc.center == (0, 0)
    RightOf(back, face, gap=5)
    AlignCenterY(back, face)
    RightOf(fin_a, back, gap=5)
    AlignTop(fin_a, back)
    Below(fin_b, fin_a, gap=5)
    AlignLeft(fin_b, fin_a)

    # in 3D: engraved face down on the dough, back on it, fins crossed on top
    Place(face, rotation=(180 deg, 0, 0), position=(0, 0, T))
    Place(back, position=(0, 0, T))
    Place(fin_a, rotation=(90 deg, 0, 0), position=(0, T / 2, 2 * T))
    Place(fin_b, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 0, 2 * T))

    assert face.disc.diameter == 60 mm, "60 mm stamp"
    assert face.label.bb.width <= 44 mm, "word at most 44 wide"
    assert face.heart.bb.height == 12 mm, "12 mm heart"
    assert fin_a.plate.bb.width == 36 mm and fin_a.plate.bb.height == 30 mm, "fins 36 x 30"
    assert D / 2 - face.border.ring.bb.width / 2 == 1 mm, "border 1 mm in from the rim"
}
