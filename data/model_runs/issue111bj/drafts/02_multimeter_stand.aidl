# Request: "A bench stand for my multimeter (90 mm wide, 185 mm tall, 50 mm deep in its
# rubber holster) so it stands tilted back 20 degrees from upright, screen towards me. 4 mm
# plywood: a back board the meter leans on (130 mm up the slope) and a ledge its bottom sits
# on (52 mm deep, square to the back board), held between two side cheeks by glued tabs in
# slots (two 20 mm tabs per edge). 3 mm of play each side of the meter (96 mm between the
# cheeks). A 50 x 70 mm window in the back board to reach the battery door. Round the cheeks'
# outer corners r4."

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
tilt = 20 deg            # back from upright
inner = 96 mm            # between the cheeks
back_len = 130 mm        # along the slope, above the ledge's top face
ledge_len = 52 mm
kx = 60 mm               # the inside corner (ledge top meets back face) in the cheek's frame
ky = 25 mm

# a point of the cheek's frame: c mm up the back board's front face from the corner, e mm
# behind it (negative: in front of it; -a with c = -b is a mm along the ledge, b under it)
def pu(c, e) = kx + c * cos(90 deg - tilt) + e * sin(90 deg - tilt)
def pv(c, e) = ky + c * sin(90 deg - tilt) - e * cos(90 deg - tilt)

def cheek() -> solid {
    prof = Polygon([(5, 0), (125, 0), (125, 30),
                    (pu(115, 14), pv(115, 14)), (pu(115, -12), pv(115, -12)),
                    (pu(12, -12), pv(12, -12)),
                    (pu(12, -52), pv(12, -52)), (pu(-16, -52), pv(-16, -52))])
    back_slots = tab_and_slot(part="slot", length=back_len + t, thickness=t, tabs=2, tab=20 mm,
                              screw=0, rotation=90 deg - tilt,
                              cx=pu((back_len - t) / 2, t / 2), cy=pv((back_len - t) / 2, t / 2))
    ledge_slots = tab_and_slot(part="slot", length=ledge_len, thickness=t, tabs=2, tab=20 mm,
                               screw=0, rotation=180 deg - tilt,
                               cx=pu(-t / 2, -ledge_len / 2), cy=pv(-t / 2, -ledge_len / 2))
    Fillet(prof, 4)
}

def board(len=100 mm, window=false) -> solid {
    body = Rectangle(bottom_left=(-inner / 2 - t, 0), width=inner + 2 * t, height=len)
    left_tabs = tab_and_slot(part="tab", length=len, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=-inner / 2 - t, cy=len / 2)
    right_tabs = tab_and_slot(part="tab", length=len, thickness=t, tabs=2, tab=20 mm, screw=0,
                              rotation=-90 deg, cx=inner / 2 + t, cy=len / 2)
    if window {
        hole door {
            w = RoundedRectangle(center=(0, len / 2 + 10), width=50, height=70, corner_radius=8)
        }
    }
}

assembly stand {
    left = cheek()
    right = cheek()
    back = board(len=back_len + t, window=true)
    ledge = board(len=ledge_len)

    # on the sheet
    RightOf(right, left, gap=5)
    AlignBottom(right, left)
    RightOf(back, right, gap=5)
    AlignBottom(back, right)
    RightOf(ledge, back, gap=5)
    AlignBottom(ledge, back)

    # in 3D: x across, y front to back, z up; the cheeks stand on edge at either side
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-inner / 2 - t, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(inner / 2, 0, 0))
    # the back board: its y runs up the slope from t under the corner, its face on the corner
    # FIX after the first valid program: W0517 (back board and cheeks collide): the board's
    # y = 0 is its bottom end, t below the corner (c = -t), not the corner; my slip
    Place(back, rotation=(90 deg - tilt, 0, 0),
          position=(0, pu(-t, t), pv(-t, t)))
    Place(ledge, rotation=(180 deg - tilt, 0, 0), position=(0, kx, ky))

    assert inner - 90 mm == 6 mm, "3 mm of play each side of a 90 mm meter"
    assert back.body.bb.height - t == 130 mm, "back board 130 mm above the ledge"
    assert ledge.body.bb.height == 52 mm, "ledge 52 mm deep"
    assert back.door.w.bb.width == 50 mm and back.door.w.bb.height == 70 mm, "50 x 70 window"
    assert left.prof.bb.bottom == 0 mm, "the cheek stands on its bottom edge"
}
