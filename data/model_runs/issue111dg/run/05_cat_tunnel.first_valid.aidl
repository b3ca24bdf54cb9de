# Request (pets): a wooden cat tunnel for the living room, 6 mm birch ply, glued.
# Two arch frames, each a half ring 400 wide and 200 tall outside with a 300 x 150 half-round
# opening (so the arch is 50 mm wide and stands on its two 50 mm feet). Seven slats
# 30 mm wide join the frames 400 mm apart (between the frames' inner faces); each slat ends
# in one 20 mm tab through a mortise in each frame, the mortises centred on the arch's
# middle radius (175) at 15, 40, 65, 90, 115, 140 and 165 degrees. The cat's name "MOCHI"
# is engraved filled (bold, 10 mm) along the top of the front frame, outside the mortises.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
R_out = 200 mm
R_in = 150 mm
R_mid = 175 mm
span = 400 mm
slat_w = 30 mm
angles = [15 deg + i * 25 deg for i in range(7)]

def frame(name="") -> solid {
    arch = Sector(center=(0, 0), radius=R_out, start_angle=0 deg, end_angle=180 deg,
                  inner_radius=R_in)
    for a in angles {
        m = tab_and_slot(part="slot", length=slat_w, thickness=t, tabs=1, tab=20 mm, screw=0,
                         rotation=a - 90 deg, cx=R_mid * cos(a), cy=R_mid * sin(a))
    }
    if name != "" {
        drawing label {
            path = Circle(center=(0, 0), radius=187, construction=true)
            w = Text(name, along=path, size=10, valign="middle", font="sans:Bold", fill=true)
        }
    }
}

def slat_part() -> solid {
    body = Rectangle(center=(0, 0), width=span + 2 * t, height=slat_w)
    left_tab = tab_and_slot(part="tab", length=slat_w, thickness=t, tabs=1, tab=20 mm,
                            screw=0, rotation=90 deg, cx=-(span + 2 * t) / 2, cy=0 mm)
    right_tab = tab_and_slot(part="tab", length=slat_w, thickness=t, tabs=1, tab=20 mm,
                             screw=0, rotation=-90 deg, cx=(span + 2 * t) / 2, cy=0 mm)
}

assembly tunnel {
    front = frame(name="MOCHI")
    back = frame()
    # front frame x in [-6, 0] facing -x, back frame x in [400, 406] facing +x
    Place(front, position=(0, 0, 0), face="left", up="up")
    Place(back, position=(span, 0, 0), face="right", up="up")

    for i in range(7) {
        slat = slat_part()
        Place(slat, position=(span / 2, (R_mid - t / 2) * cos(angles[i]),
                              (R_mid - t / 2) * sin(angles[i])),
              face=(0, cos(angles[i]), sin(angles[i])),
              up=(0, -sin(angles[i]), cos(angles[i])))
    }

    # flat on the sheet
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Below(slat[0], front, gap=10)
    AlignLeft(slat[0], front)
    for i in range(1, 7) {
        Below(slat[i], slat[i - 1], gap=5)
        AlignLeft(slat[i], slat[0])
    }

    assert front.arch.bb.width == 400 mm and front.arch.bb.height == 200 mm, "arch 400 x 200"
    assert 2 * R_in == 300 mm and R_in == 150 mm, "opening 300 x 150"
    assert len(slat) == 7, "seven slats"
    assert slat[0].body.bb.width - 2 * t == 400 mm, "frames 400 apart"
    assert slat[0].body.bb.height == 30 mm, "slats 30 wide"
}
