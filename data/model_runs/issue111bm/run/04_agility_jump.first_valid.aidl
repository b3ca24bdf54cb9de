# Request: a small-dog agility jump for the back garden, cut from 6 mm exterior ply; the bar
# is a bought 25 mm dowel, 600 mm clear between the uprights. Two uprights 150 mm wide and
# 500 mm tall with a fully rounded top. On the landing side edge of each, three open notches
# 27 mm high and 25 mm deep (round-ended) hold the dowel so a knock pushes it off; the bar's
# top sits at 200, 300 and 400 mm, and "20", "30", "40" (cm) are engraved beside the notches.
# A paw print (a 28 x 22 pad and four 11 mm toes) is cut near the top, and the dog's name
# "BISCUIT" is cut through as bold stencil letters running up the upright. Each upright
# stands in a 300 x 60 mm foot (ends r10), the two cross-halved 30 mm each (0.2 clearance).

import "std/joints.aidl"

thickness 6 mm

param span = 600 mm, min = 400, max = 1000
param up_w = 150 mm, min = 120, max = 200
param up_h = 500 mm, min = 400, max = 700

t = 6 mm
dowel = 25 mm
tops = [200 mm, 300 mm, 400 mm]

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=up_h,
                            corner_radii=[up_w / 2, up_w / 2, 0, 0])
    # notches open on the landing side (+x), centred 11.5 below the bar's top
    for h in tops {
        hole notch {
            s = Slot(center=(up_w / 2, h - 11.5), length=50, width=27)
        }
        drawing mark {
            n = Text(str(round(h / 10 mm)), position=(up_w / 2 - 40, h - 11.5), size=10,
                     valign="middle")
        }
    }
    hole paw {
        pad = Ellipse(center=(0, up_h - 70), rx=14, ry=11)
        t1 = Circle(center=(-19, up_h - 55), diameter=11)
        t2 = Circle(center=(-7, up_h - 45), diameter=11)
        t3 = Circle(center=(7, up_h - 45), diameter=11)
        t4 = Circle(center=(19, up_h - 55), diameter=11)
    }
    hole name {
        w = Text("BISCUIT", position=(-up_w / 2 + 40, 230), size=18, rotation=90 deg,
                 font="sans:Bold", valign="middle", stencil=true, max_width=220 mm)
    }
    halving = cross_halving(depth=30 mm, thickness=t, clearance=0.2 mm, rotation=180 deg,
                            cx=0, cy=0)
}

def foot() -> solid {
    bar = RoundedRectangle(bottom_left=(-150, 0), width=300, height=60, corner_radius=10)
    halving = cross_halving(depth=30 mm, thickness=t, clearance=0.2 mm, cx=0, cy=60)
}

assembly jump {
    for i in range(2) {
        ups = upright()
        feet = foot()
        # upright across the bar: its x -> world y (travel), y -> z, thickness -> world x
        Place(ups, rotation=(90 deg, 0, 90 deg),
              position=((2 * i - 1) * (span / 2 + t / 2) - t / 2, 0, 0))
        # foot along the bar: its x -> world x, y -> z, thickness -> world y
        Place(feet, rotation=(90 deg, 0, 0), position=((2 * i - 1) * (span / 2 + t / 2), t / 2, 0))
    }
    # on the sheet
    RightOf(ups[1], ups[0], gap=10)
    AlignBottom(ups[1], ups[0])
    RightOf(feet[0], ups[1], gap=10)
    AlignBottom(feet[0], ups[1])
    Above(feet[1], feet[0], gap=10)
    AlignLeft(feet[1], feet[0])

    assert len(ups) == 2 and len(feet) == 2, "two uprights, two feet"
    assert ups[0].body.bb.width == 150 mm and ups[0].body.bb.height == 500 mm, "uprights 150 x 500"
    assert feet[0].bar.bb.width == 300 mm and feet[0].bar.bb.height == 60 mm, "feet 300 x 60"
    assert len(ups[0].notch) == 3, "three heights"
    for k in range(3) {
        assert ups[0].notch[k].s.bb.bottom - ups[0].body.bb.bottom + dowel == [200 mm, 300 mm, 400 mm][k],
            "bar top at 20 / 30 / 40 cm"
    }
    assert ups[0].notch[0].s.width == 27 mm, "notches 27 high"
    assert ups[0].body.bb.right - ups[0].notch[0].s.bb.left == 25 mm, "notches 25 deep"
}
