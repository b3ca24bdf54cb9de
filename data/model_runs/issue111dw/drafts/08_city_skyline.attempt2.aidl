# Request (gifts): a two-layer city skyline keepsake for a couple's first trip, 3 mm ply.
# Two skyline layers 240 wide stand 16 mm apart (centre to centre) in a base 250 x 45 with R5
# corners, each glued in by two 30 mm tenons (0.1 mm clearance in the mortises).
# Back layer: a 20 mm band with nine towers rising from it (centres, widths and heights above
# the band in the list below), a spire 8 wide and 25 tall on the tallest, a dome R15 on the
# fourth from the right. Front layer: a 35 mm band with five lower buildings, each with four
# windows 4 x 5 (two columns 12 mm apart, rows 42 and 50 mm above the band's foot), and PARIS
# cut through the band as 20 mm stencil letters. "OUR FIRST TRIP · 2019" engraved filled,
# 5 mm tall, on the base's front margin.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

w = 240 mm
# [centre x, width, height above the band] in mm
towers = [[-100, 30, 70], [-70, 24, 95], [-45, 26, 80], [-18, 20, 110], [5, 28, 85],
          [30, 18, 100], [55, 30, 75], [85, 24, 90], [108, 20, 72]]
houses = [[-95, 40, 62], [-50, 30, 58], [-10, 36, 66], [35, 32, 60], [85, 44, 64]]
back_band = 20 mm
front_band = 35 mm
gap = 16 mm

def layer_tenons() -> hole {
    j = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=30 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=-t)
}

assembly city_skyline {
    solid back {
        band = Rectangle(bottom_left=(-w / 2, -t), width=w, height=back_band + t)
        for i in range(len(towers)) {
            tw = Rectangle(bottom_left=((towers[i][0] - towers[i][1] / 2) * 1 mm, 0),
                           width=towers[i][1] * 1 mm, height=back_band + towers[i][2] * 1 mm)
        }
        spire = Triangle(center=(-18 mm, back_band + 110 mm + 12.5 mm - 1 mm), base=8, height=25)
        dome = Circle(center=(55 mm, back_band + 75 mm), radius=15)
        tenons = layer_tenons()
    }

    solid front {
        band = Rectangle(bottom_left=(-w / 2, -t), width=w, height=front_band + t)
        for i in range(len(houses)) {
            hs = Rectangle(bottom_left=((houses[i][0] - houses[i][1] / 2) * 1 mm, 0),
                           width=houses[i][1] * 1 mm, height=houses[i][2] * 1 mm)
        }
        hole windows {
            for i in range(len(houses)) {
                for r in range(2) {
                    for c in range(2) {
                        win = Rectangle(center=((houses[i][0] + (c - 0.5) * 12) * 1 mm,
                                                42 mm + r * 8 mm),
                                        width=4, height=5)
                    }
                }
            }
        }
        hole name {
            n = Text("PARIS", position=(0, front_band / 2), size=20, font="sans:Bold",
                     valign="middle", stencil=true)
        }
        tenons = layer_tenons()
    }

    solid base {
        p = RoundedRectangle(center=(0, 0), width=250, height=45, corner_radius=5)
        mf = tab_and_slot(part="slot", length=w, thickness=t, tabs=2, tab=30 mm, screw=0,
                          clearance=0.1 mm, cx=0 mm, cy=-gap / 2)
        mb = tab_and_slot(part="slot", length=w, thickness=t, tabs=2, tab=30 mm, screw=0,
                          clearance=0.1 mm, cx=0 mm, cy=gap / 2)
        drawing message {
            m = Text("OUR FIRST TRIP · 2019", position=(0, -16 mm), size=5, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # flat on the sheet
    RightOf(front, back, gap=6)
    AlignBottom(front, back)
    Below(base, back, gap=6)
    AlignLeft(base, back)

    # in 3D: the base flat, the layers standing in their mortises
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, -gap / 2 + t / 2, t), face="front", up="up")
    Place(back, position=(0, gap / 2 + t / 2, t), face="front", up="up")

    assert back.band.bb.width == 240 mm and front.band.bb.width == 240 mm, "layers 240 wide"
    assert base.p.bb.width == 250 mm and base.p.bb.height == 45 mm, "base 250 x 45"
    assert base.mb.slot[0].bb.center_y - base.mf.slot[0].bb.center_y == 16 mm, "16 apart"
    assert len(towers) == 9 and len(houses) == 5, "nine towers, five houses"
    assert sum([len(r) for r in front.windows.win]) == 20, "four windows a house"
    assert back.spire.bb.top - (back.band.bb.bottom + 3 mm) == 20 mm + 110 mm + 25 mm - 1 mm,
        "spire on the tallest tower"
    assert front.name.bb.top <= front.band.bb.top - 3 mm, "PARIS inside the band"
    assert front.name.bb.bottom >= front.band.bb.bottom + 3 mm + 3 mm, "PARIS above the base"
    assert front.windows.bb.bottom >= front.band.bb.top + 2 mm, "windows above the band"
    assert back.bb.height >= front.bb.height + 30 mm, "the back layer shows over the front"
    assert base.message.bb.top <= base.mf.slot[0].bb.bottom - 1 mm, "message in the margin"
    assert base.message.bb.bottom >= base.p.bb.bottom + 1 mm, "message on the base"
}
