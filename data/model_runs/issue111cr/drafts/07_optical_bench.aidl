# Request: a school optical bench for finding a lens's focal length. Rail of 6 mm ply, 500 x
# 80 mm, with a 6.2 mm guide slot along its centre line from 235 mm left to 235 mm right of the
# middle; a scale engraved from its front edge: 46 ticks 10 mm apart (0 to 450 mm, the 0 at
# 225 mm left of the middle), 4 mm long, every 5th 7 mm long and numbered in cm (0, 5, ... 45;
# 3.5 mm digits, baseline 9 mm from the edge), "cm" after the 45, and "OPTICAL BENCH" engraved
# 6 mm high 30 mm behind the centre line. Two riders of 3 mm ply, each a foot and an upright:
# foot 60 x 40 mm with a pointer (8 mm base, 5 mm long) at the middle of its front edge, two 6 mm
# holes for dowel pins 40 mm apart on the centre line (they run in the rail's slot), and 2 slots
# for the upright's 2 tabs (10 mm); upright 80 mm wide above a 40 mm wide stem, standing 130 mm
# above the foot with 4 mm corners on top. The lens upright has a 38 mm hole for the lens, its
# centre 90 mm above the foot, and "LENS" engraved 4 mm high under it; the screen upright has a
# 60 x 60 mm engraved 10 mm grid centred 90 mm above the foot and "SCREEN" under it. Assembled:
# lens at the 200 mm mark, screen at 350 mm. Five parts.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
RAIL_T = 6 mm
ZERO_X = -225 mm
AXIS_H = 90 mm

def foot() -> solid {
    body = Rectangle(center=(0, 0), width=60, height=40)
    pointer = Polygon([(-4, -20), (4, -20), (0, -25)])
    joint = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=2, tab=10 mm, screw=0,
                         rotation=90 deg, cx=0 mm, cy=0 mm)
    hole pins {
        a = Circle(center=(-20, 0), diameter=6)
        b = Circle(center=(20, 0), diameter=6)
    }
}

def upright(lens=true) -> solid {
    # y = 0 is the foot's top face; the tabs reach T below it
    stem = Rectangle(bottom_left=(-20, -T), width=40, height=40 + T)
    plate = RoundedRectangle(bottom_left=(-40, 40), width=80, height=90,
                             corner_radii=[4, 4, 0, 0])
    joint = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=2, tab=10 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-T)
    if lens {
        hole lens_hole { c = Circle(center=(0, AXIS_H), diameter=38) }
        drawing label { t = Text("LENS", position=(0, 52), size=4) }
    } else {
        drawing grid {
            for i in range(7) {
                v = Line((-30 + i * 10, AXIS_H - 30), (-30 + i * 10, AXIS_H + 30))
                h = Line((-30, AXIS_H - 30 + i * 10), (30, AXIS_H - 30 + i * 10))
            }
        }
        drawing label { t = Text("SCREEN", position=(0, 52), size=4) }
    }
}

assembly optical_bench {
    solid rail {
        thickness 6 mm
        body = Rectangle(center=(0, 0), width=500, height=80)
        hole guide { s = Slot(start=(-235, 0), end=(235, 0), width=6.2) }
        drawing scale {
            for i in range(46) {
                tick = Line((ZERO_X + i * 10, -40), (ZERO_X + i * 10, -40 + (7 if i % 5 == 0 else 4)))
            }
            for k in range(10) {
                num = Text(str(5 * k), position=(ZERO_X + k * 50, -31), size=3.5)
            }
            unit = Text("cm", position=(ZERO_X + 462, -31), size=3.5)
            title = Text("OPTICAL BENCH", position=(0, 30), size=6)
        }
    }
    lens_foot = foot()
    lens = upright(lens=true)
    screen_foot = foot()
    screen = upright(lens=false)

    # flat on the sheet
    Below(lens_foot, rail, gap=8 mm)
    AlignLeft(lens_foot, rail)
    RightOf(screen_foot, lens_foot, gap=8 mm)
    AlignTop(screen_foot, lens_foot)
    RightOf(lens, screen_foot, gap=8 mm)
    AlignTop(lens, screen_foot)
    RightOf(screen, lens, gap=8 mm)
    AlignTop(screen, lens)

    # assembled: riders on the rail at the 200 and 350 mm marks
    Place(rail, position=(0, 0, 0))
    Place(lens_foot, position=(ZERO_X + 200, 0, RAIL_T))
    Place(lens, position=(ZERO_X + 200 - T / 2, 0, RAIL_T + T), face="right", up="up")
    Place(screen_foot, position=(ZERO_X + 350, 0, RAIL_T))
    # FIX after the first valid program: the screen's engraved grid faced +x, away from the lens
    # (the light comes from the 0 end); its top face now looks -x, toward the lens
    Place(screen, position=(ZERO_X + 350 + T / 2, 0, RAIL_T + T), face="left", up="up")

    # the request's numbers
    assert rail.body.bb.width == 500 mm and rail.body.bb.height == 80 mm, "rail 500 x 80"
    assert rail.guide.s.width == 6.2 mm and rail.guide.s.bb.width == 470 mm + 6.2 mm, "guide slot"
    assert len(rail.scale.tick) == 46, "46 ticks"
    assert rail.scale.tick[1].start.x - rail.scale.tick[0].start.x == 10 mm, "10 mm apart"
    assert rail.scale.tick[0].start.x - rail.body.bb.center_x == -225 mm, "0 at 225 left"
    assert len(rail.scale.num) == 10 and rail.scale.num[9].text == "45", "0 to 45 cm"
    assert lens_foot.body.bb.width == 60 mm and lens_foot.body.bb.height == 40 mm, "foot 60 x 40"
    assert lens_foot.pins.b.center.x - lens_foot.pins.a.center.x == 40 mm, "pins 40 mm apart"
    assert lens.plate.bb.width == 80 mm and lens.stem.bb.width == 40 mm, "upright 80, stem 40"
    assert lens.plate.bb.top - lens.joint.gap[0].bb.top == 130 mm, "130 above the foot"
    assert lens.lens_hole.c.diameter == 38 mm, "38 mm lens"
    assert lens.lens_hole.c.center.y - lens.joint.gap[0].bb.top == 90 mm, "axis 90 above the foot"
    assert len(screen.grid.v) == 7 and len(screen.grid.h) == 7, "10 mm grid, 60 x 60"
}
