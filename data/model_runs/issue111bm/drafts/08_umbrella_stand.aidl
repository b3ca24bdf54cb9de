# Request: an umbrella stand for the hallway, cut from 6 mm birch ply: an open-top,
# finger-jointed box 220 x 220 mm and 480 mm high (20 mm fingers), with a cross of two
# cross-halved dividers (300 mm high, 0.5 mm short of the walls at each end, halved 150 mm
# each, 0.2 clearance) standing on its floor to keep four umbrellas apart. The front and back
# panels carry "rain": 4 staggered rows of 4 rain-drop openings (a 16 mm circle drawn up to a
# point 20 mm above its centre, 40 mm apart in a row, rows 45 mm apart), the top row's top
# 40 mm below the panel's top edge; "THE HARRISONS" engraved filled (bold sans, 12 mm) on the
# front, 25 mm below the rain.

import "std/joints.aidl"

thickness 6 mm

param side = 220 mm, min = 180, max = 300
param tall = 480 mm, min = 400, max = 600
param div_h = 300 mm, min = 150, max = 400

t = 6 mm
inner = side - 2 * t

def rain() -> hole {
    drop = Hull(Circle(center=(0, 0), diameter=16), Point(0, 20))
    drops = GridPattern(drop, 4, 4, (40, -45), stagger=true)
}

def divider(from_top=true) -> solid {
    board = Rectangle(bottom_left=(-(inner - 1 mm) / 2, 0), width=inner - 1 mm, height=div_h)
    if from_top {
        halving = cross_halving(depth=div_h / 2, thickness=t, clearance=0.2 mm, cx=0, cy=div_h)
    } else {
        halving = cross_halving(depth=div_h / 2, thickness=t, clearance=0.2 mm,
                                rotation=180 deg, cx=0, cy=0)
    }
}

assembly stand {
    box = finger_box(length=side, depth=side, height=tall, thickness=t, finger=20 mm,
                     closed=false)

    rain_f = rain()
    rain_b = rain()
    # FIX after the first valid program: W0401 found my loop aligning both patterns to the
    # front (a slip; harmless, as the net stacks front and back on one centre line)
    AlignCenterX(rain_f, box.front)
    AlignCenterX(rain_b, box.back)
    rain_f.bb.top == box.front.bb.top - 40 mm
    rain_b.bb.top == box.back.bb.top - 40 mm
    CutInto(rain_f, box.front)
    CutInto(rain_b, box.back)

    drawing name {
        n = Text("THE HARRISONS", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(name, box.front)
    name.bb.top == rain_f.bb.bottom - 25 mm
    CutInto(name, box.front)

    across = divider(from_top=true)
    along = divider(from_top=false)
    # standing on the floor (z = t): `across` in the x-z plane, `along` in the y-z plane
    Place(across, rotation=(90 deg, 0, 0), position=(0, t / 2, t))
    Place(along, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, t))
    # on the sheet, beside the box's net
    RightOf(across, box, gap=10)
    AlignBottom(across, box)
    Above(along, across, gap=10)
    AlignLeft(along, across)

    assert box.front.bb.width == 220 mm and box.front.bb.height == 480 mm, "220 wide, 480 high"
    assert across.board.bb.height == 300 mm, "dividers 300 high"
    assert across.board.bb.width == 220 mm - 2 * 6 mm - 1 mm, "0.5 short of each wall"
    assert len(rain_f.drops) == 16, "4 rows of 4 drops"
    assert box.front.bb.top - rain_f.bb.top == 40 mm, "rain 40 below the top"
    assert rain_f.bb.bottom - name.bb.top == 25 mm, "name 25 below the rain"
}
