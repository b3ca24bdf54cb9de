# Request: a toy castle for a child's knights, 3 mm plywood, finger-jointed and glued. A square
# keep 200 x 200 mm outside, walls 120 mm high on a 200 x 200 floor. Every wall is crenellated:
# 6 gaps 15 mm wide and 12 mm deep on 30 mm centres, centred on the wall. Every wall has two
# arrow slits 6 x 30 mm, 60 mm either side of its middle, centred 70 mm above the bottom. The
# front wall has an arched gate 60 mm wide and 80 mm tall (round top), standing on a 5 mm sill
# above the floor, and "CAMELOT" engraved filled (serif, 7 mm) between the gate and the
# crenellations. A separate drawbridge, the gate's shape 2 mm larger all round, has engraved
# planks and two 3 mm holes for its strings, 15 mm down from the top, 30 mm apart; it lies open
# in front of the gate.

import "std/joints.aidl"

thickness 3 mm

param side = 200 mm, min = 150 mm, max = 300 mm
param wall_h = 120 mm, min = 90 mm, max = 180 mm
gate_w = 60 mm
gate_h = 80 mm
sill = 5 mm
crenel_w = 15 mm
crenel_d = 12 mm
crenel_pitch = 30 mm

def wall(front=false, bottom="fingers", sides="fingers") -> solid {
    p = finger_panel(width=side, height=wall_h, thickness=3 mm, finger=12 mm,
                     bottom=bottom, right=sides, top="flat", left=sides)
    hole crenel {
        r = Rectangle(center=(-2.5 * crenel_pitch, wall_h / 2 - crenel_d / 2 + 1 mm), width=crenel_w,
                      height=crenel_d + 2 mm)
    }
    crenels = LinearPattern(crenel, 6, (crenel_pitch, 0))
    hole slit_l { s = Slot(center=(-60, -wall_h / 2 + 70), length=30, width=6, rotation=90 deg) }
    hole slit_r { s = Slot(center=(60, -wall_h / 2 + 70), length=30, width=6, rotation=90 deg) }
    if front {
        hole gate {
            door = Rectangle(bottom_left=(-gate_w / 2, -wall_h / 2 + 3 mm + sill), width=gate_w,
                             height=gate_h - gate_w / 2)
            arch = Circle(center=(0, -wall_h / 2 + 3 mm + sill + gate_h - gate_w / 2), radius=gate_w / 2)
        }
        drawing name {
            word = Text("CAMELOT", position=(0, -wall_h / 2 + 3 mm + sill + gate_h + 4 mm), size=7,
                        font="serif", fill=true)
        }
    }
}

def drawbridge() -> solid {
    deck = Rectangle(bottom_left=(-gate_w / 2 - 2 mm, -2 mm), width=gate_w + 4 mm, height=gate_h - gate_w / 2 + 2 mm)
    top = Circle(center=(0, gate_h - gate_w / 2), radius=gate_w / 2 + 2 mm)
    hole strings {
        a = Circle(center=(-15, gate_h + 2 mm - 15 mm), diameter=3)
        b = Circle(center=(15, gate_h + 2 mm - 15 mm), diameter=3)
    }
    drawing planks {
        for i in range(7) {
            l = Line((-24 + 8 * i, 4), (-24 + 8 * i, gate_h - gate_w / 2 - 4 mm))
        }
    }
}

assembly toy_castle {
    floor = finger_panel(width=side, height=side, thickness=3 mm, finger=12 mm,
                         bottom="slots", right="fingers", top="slots", left="fingers")
    front = wall(front=true)
    back = wall()
    left = wall(bottom="slots", sides="slots")
    right = wall(bottom="slots", sides="slots")
    bridge = drawbridge()

    # on the sheet: a net round the floor
    Fixed(floor)
    Below(front, floor, gap=5)
    AlignCenterX(front, floor)
    Above(back, floor, gap=5)
    AlignCenterX(back, floor)
    LeftOf(left, floor, gap=5)
    AlignCenterY(left, floor)
    RightOf(right, floor, gap=5)
    AlignCenterY(right, floor)
    RightOf(bridge, front, gap=5)
    AlignBottom(bridge, front)

    # in 3D: standing on z = 0, centred on x = y = 0, the drawbridge open in front of the gate
    Place(floor, position=(0, 0, 0), face="up")
    Place(front, position=(0, -side / 2 + 3 mm, wall_h / 2), face="front", up="up")
    Place(back, position=(0, side / 2 - 3 mm, wall_h / 2), face="back", up="up")
    Place(left, position=(-side / 2 + 3 mm, 0, wall_h / 2), face="left", up="up")
    Place(right, position=(side / 2 - 3 mm, 0, wall_h / 2), face="right", up="up")
    Place(bridge, position=(0, -side / 2, 0), face="up", up="front")

    assert floor.outline.width == 200 mm and floor.outline.height == 200 mm, "200 x 200 keep"
    assert front.p.outline.height == 120 mm, "walls 120 high"
    assert len(front.crenels) == 6, "6 crenels a wall"
    assert front.crenels[0].r.width == 15 mm, "crenels 15 wide"
    assert front.p.outline.bb.top - front.crenels[0].r.bb.bottom == 12 mm, "crenels 12 deep"
    assert front.crenels[1].r.center.x - front.crenels[0].r.center.x == 30 mm, "crenels on 30 mm centres"
    assert abs(front.crenels[0].r.center.x + front.crenels[5].r.center.x) < 0.01 mm, "crenels centred"
    assert front.slit_r.s.center.x - front.slit_l.s.center.x == 120 mm, "slits 60 either side"
    assert front.slit_l.s.center.y - front.p.outline.bb.bottom == 70 mm, "slits 70 up"
    assert front.gate.bb.width == 60 mm and front.gate.bb.height == 80 mm, "gate 60 x 80"
    assert front.gate.bb.bottom - front.p.outline.bb.bottom == 3 mm + 5 mm, "5 mm sill above the floor"
    assert bridge.bb.width == 64 mm and bridge.bb.height == 84 mm, "drawbridge 2 mm larger all round"
    assert bridge.strings.b.center.x - bridge.strings.a.center.x == 30 mm, "string holes 30 apart"
    assert front.name.bb.bottom > front.gate.bb.top and front.name.bb.top < front.crenels[0].r.bb.bottom,
        "name between gate and crenels"
}
