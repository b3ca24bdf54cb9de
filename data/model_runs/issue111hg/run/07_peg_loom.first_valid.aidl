# Request (crafts): a peg loom for weaving rugs and scarves, from 6 mm birch ply.
# Twenty flat pegs, 12 mm wide and 160 mm long with a rounded top (6 mm radii) and a
# 3 x 10 mm eye for the warp, centred 26 mm from the bottom. The base is a beam 500 mm long
# and 46 mm tall: a top and a bottom plate, each 500 x 50 mm, with twenty 12.3 x 6.3 mm
# mortises for the pegs at a 22 mm pitch (centred), held by two end frames, 100 mm wide and
# 52 mm tall with 8 mm rounded top corners, by one 30 mm glued tab at each end of each
# plate. The plates' top faces are 6 mm and 40 mm above the frames' bottoms, so the peg
# eyes sit in the gap between the plates. The numbers 1 to 20 engraved (5 mm) on the top
# plate beside the mortises.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
pegs = 20
pitch = 22 mm
peg_w = 12 mm
peg_l = 160 mm
plate_l = 500 mm
plate_w = 50 mm
frame_w = 100 mm
frame_h = 52 mm
low = 6 mm    # the bottom plate's underside above the table
high = 40 mm  # the top plate's underside above the table
first_x = -(pegs - 1) * pitch / 2

def peg_t() -> solid {
    body = RoundedRectangle(center=(0, peg_l / 2), width=peg_w, height=peg_l,
                            corner_radii=[6 mm, 6 mm, 0 mm, 0 mm])
    hole eye {
        s = Slot(center=(0, 26 mm), length=10, width=3, rotation=90 deg)
    }
}

def plate_t(numbered=false) -> solid {
    body = Rectangle(center=(0, 0), width=plate_l, height=plate_w)
    left_tab = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=-plate_l / 2, cy=0 mm)
    right_tab = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=1, tab=30 mm,
                             screw=0, rotation=-90 deg, cx=plate_l / 2, cy=0 mm)
    hole mortise {
        m = Rectangle(center=(first_x, 0), width=peg_w + 0.3 mm, height=t + 0.3 mm)
    }
    row = LinearPattern(mortise, pegs, (pitch, 0))
    if numbered {
        drawing numbers {
            for i in range(pegs) {
                n = Text(str(i + 1), (first_x + i * pitch, -14 mm), size=5, valign="middle")
            }
        }
    }
}

def frame_t() -> solid {
    body = RoundedRectangle(center=(0, frame_h / 2), width=frame_w, height=frame_h,
                            corner_radii=[8 mm, 8 mm, 0 mm, 0 mm])
    lower = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=1, tab=30 mm,
                         screw=0, clearance=0.1 mm, cx=0 mm, cy=low + t / 2)
    upper = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=1, tab=30 mm,
                         screw=0, clearance=0.1 mm, cx=0 mm, cy=high + t / 2)
}

assembly loom {
    top = plate_t(numbered=true)
    bottom = plate_t()
    left_frame = frame_t()
    right_frame = frame_t()

    Below(bottom, top, gap=10)
    AlignLeft(bottom, top)
    Below(left_frame, bottom, gap=10)
    AlignLeft(left_frame, bottom)
    RightOf(right_frame, left_frame, gap=10)
    AlignTop(right_frame, left_frame)

    for i in range(pegs) {
        peg = peg_t()
        peg.bb.center == (-240 mm + i * (peg_w + 5 mm), -330 mm)
        Place(peg, position=(first_x + i * pitch, t / 2, 0), face="front", up="up")
    }

    Place(top, position=(0, 0, high), face="up")
    Place(bottom, position=(0, 0, low), face="up")
    Place(left_frame, position=(-plate_l / 2 + t, 0, 0), face="left", up="up")
    Place(right_frame, position=(plate_l / 2 - t, 0, 0), face="right", up="up")

    assert len(peg) == 20, "twenty pegs"
    assert len(top.row) == 20 and len(bottom.row) == 20, "twenty mortises in each plate"
    assert top.row[1].m.center.x - top.row[0].m.center.x == 22 mm, "22 mm pitch"
    assert peg[0].body.bb.height == 160 mm and peg[0].body.bb.width == 12 mm, "peg size"
    assert peg[0].eye.s.center.y - peg[0].body.bb.bottom == 26 mm, "eye 26 from the bottom"
    assert high + t - low == 40 mm, "beam 40 + 6 tall"
    assert distance(top.numbers, top.mortise) >= 2 mm, "numbers clear of the mortises"
}
