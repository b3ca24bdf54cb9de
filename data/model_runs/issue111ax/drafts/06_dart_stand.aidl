# Request (sport): a stand for my three steel-tip darts by the oche, 3 mm ply, glued. A base
# plate and a top plate, both 130 x 60 mm with 5 mm rounded corners, held 60 mm apart
# (clear space between them) by two 40 mm wide uprights whose two 10 mm tabs at each end go
# through mortises in both plates. The uprights stand 52 mm either side of the centre. The
# top plate has three 8 mm holes for the barrels, 32 mm apart in a row, 5 mm behind the
# plate's middle, and "DARTS" engraved 6 mm tall along its front edge. The base has a 2 mm
# seat under each barrel hole for the point.
units mm
thickness 3 mm
import "std/joints.aidl"

param W = 130 mm, min = 110, max = 200
param D = 60 mm, min = 50, max = 100
param clear = 60 mm, min = 40, max = 120
T = 3 mm
UX = 52 mm       # each upright's plane from the centre
UW = 40 mm       # the upright's width (front to back)
PITCH = 32 mm

def upright_panel() -> solid {
    body = Rectangle(center=(0, 0), width=UW, height=clear + 2 * T)
    upper = tab_and_slot(part="tab", length=UW, thickness=T, tabs=2, tab=10 mm, screw=0,
                         cx=0, cy=(clear + 2 * T) / 2)
    lower = tab_and_slot(part="tab", length=UW, thickness=T, tabs=2, tab=10 mm, screw=0,
                         rotation=180 deg, cx=0, cy=-(clear + 2 * T) / 2)
}

assembly dart_stand {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=W, height=D, corner_radius=5)
        left_slot = tab_and_slot(part="slot", length=UW, thickness=T, tabs=2, tab=10 mm,
                                 screw=0, rotation=90 deg, cx=-UX, cy=0)
        right_slot = tab_and_slot(part="slot", length=UW, thickness=T, tabs=2, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=UX, cy=0)
        hole seats {
            for i in range(3) {
                s = Circle(center=((i - 1) * PITCH, 5), diameter=2)
            }
        }
    }

    solid top {
        body = RoundedRectangle(center=(0, 0), width=W, height=D, corner_radius=5)
        left_slot = tab_and_slot(part="slot", length=UW, thickness=T, tabs=2, tab=10 mm,
                                 screw=0, rotation=90 deg, cx=-UX, cy=0)
        right_slot = tab_and_slot(part="slot", length=UW, thickness=T, tabs=2, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=UX, cy=0)
        hole barrels {
            for i in range(3) {
                b = Circle(center=((i - 1) * PITCH, 5), diameter=8)
            }
        }
        drawing label {
            t = Text("DARTS", position=(0, -D / 2 + 9), size=6, valign="middle")
        }
    }

    left = upright_panel()
    right = upright_panel()

    # on the sheet
    RightOf(top, base, gap=6)
    AlignCenterY(top, base)
    Below(left, base, gap=6)
    AlignLeft(left, base)
    RightOf(right, left, gap=6)
    AlignCenterY(right, left)

    # assembled: plates flat, uprights standing in the planes x = -UX and x = UX
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, T + clear))
    # (u, v, w) -> (w, u, v): width along y, height up, thickness along x
    Place(left, position=(-UX - T / 2, 0, (clear + 2 * T) / 2), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(UX - T / 2, 0, (clear + 2 * T) / 2), rotation=(90 deg, 0, 90 deg))

    assert base.body.width == 130 mm and base.body.height == 60 mm, "130 x 60 plates"
    assert left.body.height - 2 * T == 60 mm, "60 mm between the plates"
    assert left.body.width == 40 mm, "40 mm uprights"
    assert len(top.barrels.b) == 3, "three darts"
    assert top.barrels.b[1].center.x - top.barrels.b[0].center.x == 32 mm, "32 mm apart"
    assert top.barrels.b[0].diameter == 8 mm, "8 mm barrel holes"
    assert top.barrels.b[0].center.y - top.body.center.y == 5 mm, "5 mm behind the middle"
    assert top.right_slot.bb.center_x - top.body.center.x == 52 mm, "uprights 52 mm out"
    assert top.barrels.b[2].center.x + 4 mm < top.right_slot.bb.left - 5 mm,
        "barrels clear of the mortises"
    assert top.label.bb.bottom > top.body.bb.bottom + 2 mm, "label on the plate"
    assert top.label.bb.top < top.barrels.b[0].center.y - 4 mm - 2 mm, "label clear of the holes"
}
