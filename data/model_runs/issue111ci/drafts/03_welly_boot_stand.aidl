# Request: a stand for three pairs of wellies upside down by the back door, 9 mm exterior ply.
# A 420 x 220 mm base with 24 drain holes of 10 mm (4 rows at 25 and 85 mm either side of the
# middle, 6 columns 60 mm apart). Standing on it, 110 mm apart (centre to centre), two
# 400 mm "combs": a solid band 80 mm tall with three 50 mm wide fingers rising 240 mm above
# it (tops rounded to a half circle, 130 mm apart), so the finger tops are 320 mm above the
# base; one boot goes over each finger. Each comb has three 40 mm tenons through the base.
# Two 60 mm tall spacers between the combs, 175 mm either side of the middle, stand on the
# base with a 30 mm tenon through each comb. "WELLIES" engraved filled, 22 mm bold, on the
# front comb's band. Glued, slots 0.1 mm over.

import "std/joints.aidl"

thickness 9 mm

t = 9 mm
fit = 0.1 mm
base_w = 420 mm
base_d = 220 mm
comb_w = 400 mm
band = 80 mm
finger_w = 50 mm
finger_h = 240 mm
finger_pitch = 130 mm
comb_gap = 110 mm           # comb middle planes, centre to centre
spacer_h = 60 mm
spacer_x = 175 mm

def comb(front=false) -> solid {
    strip = Rectangle(bottom_left=(-comb_w / 2, -t), width=comb_w, height=band + t)
    for i in range(3) {
        finger = RoundedRectangle(center=((i - 1) * finger_pitch, band + finger_h / 2 - 1 mm),
                                  width=finger_w, height=finger_h + 2 mm,
                                  corner_radii=[finger_w / 2, finger_w / 2, 0, 0])
    }
    tenons = tab_and_slot(part="tab", length=comb_w, thickness=t, tabs=3, tab=40 mm, screw=0,
                          rotation=180 deg, cx=0, cy=-t)
    sl = tab_and_slot(part="slot", length=spacer_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                      clearance=fit, rotation=90 deg, cx=-spacer_x, cy=spacer_h / 2)
    sr = tab_and_slot(part="slot", length=spacer_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                      clearance=fit, rotation=90 deg, cx=spacer_x, cy=spacer_h / 2)
    if front {
        drawing label {
            word = Text("WELLIES", position=(0, band / 2), size=22, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }
}

def spacer() -> solid {
    body = Rectangle(center=(0, spacer_h / 2), width=comb_gap + t, height=spacer_h)
    l = tab_and_slot(part="tab", length=spacer_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                     rotation=90 deg, cx=-(comb_gap + t) / 2, cy=spacer_h / 2)
    r = tab_and_slot(part="tab", length=spacer_h, thickness=t, tabs=1, tab=30 mm, screw=0,
                     rotation=-90 deg, cx=(comb_gap + t) / 2, cy=spacer_h / 2)
}

assembly stand {
    solid base {
        plate = Rectangle(center=(0, 0), width=base_w, height=base_d)
        mf = tab_and_slot(part="slot", length=comb_w, thickness=t, tabs=3, tab=40 mm, screw=0,
                          clearance=fit, cx=0, cy=-comb_gap / 2)
        mb = tab_and_slot(part="slot", length=comb_w, thickness=t, tabs=3, tab=40 mm, screw=0,
                          clearance=fit, cx=0, cy=comb_gap / 2)
        hole drain {
            for j in range(4) {
                for i in range(6) {
                    d = Circle(center=(-150 mm + i * 60 mm, [-85, -25, 25, 85][j] * 1 mm),
                               diameter=10)
                }
            }
        }
    }
    front = comb(front=true)
    back = comb()
    sp_l = spacer()
    sp_r = spacer()

    # flat on the sheet
    Above(front, base, gap=10)
    Above(back, front, gap=10)
    RightOf(sp_l, base, gap=10)
    RightOf(sp_r, base, gap=10)
    Above(sp_r, sp_l, gap=10)
    AlignLeft(front, base)
    AlignLeft(back, base)
    AlignBottom(sp_l, base)

    # in 3D: x along the stand, y front to back, z up
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, -comb_gap / 2 + t / 2, t), rotation=(90 deg, 0, 0))
    Place(back, position=(0, comb_gap / 2 + t / 2, t), rotation=(90 deg, 0, 0))
    Place(sp_l, position=(-spacer_x - t / 2, 0, t), rotation=(90 deg, 0, 90 deg))
    Place(sp_r, position=(spacer_x - t / 2, 0, t), rotation=(90 deg, 0, 90 deg))

    assert base.plate.bb.width == 420 mm and base.plate.bb.height == 220 mm, "base 420 x 220"
    assert len(base.drain.d) * len(base.drain.d[0]) == 24, "24 drain holes"
    assert len(front.finger) == 3 and len(back.finger) == 3, "three fingers a comb: three pairs"
    assert front.finger[0].bb.top - front.strip.bb.top == 240 mm, "fingers 240 mm above the band"
    assert front.finger[0].bb.top == 320 mm, "finger tops 320 mm above the base"
    assert front.finger[1].center.x - front.finger[0].center.x == 130 mm, "fingers 130 apart"
    assert base.mb.slot[0].bb.center_y - base.mf.slot[0].bb.center_y == 110 mm, "combs 110 apart"
}
