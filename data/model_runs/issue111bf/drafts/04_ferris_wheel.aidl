# Request (toys): a toy Ferris wheel for my niece's shelf, 3 mm ply, 5 parts. Two identical wheels
# 180 mm across the rim (rim 10 mm wide), 8 spokes 6 mm wide to a 30 mm hub with a 6 mm hole
# (press fit on a 6 mm dowel axle), and 8 round cabins 20 mm across on the rim's outside, each
# with a 10 mm window. Two A-frame stands (160 mm wide at the foot, 30 mm at the top, rounded r8),
# each with a 6.5 mm axle hole (the dowel turns in it) 130 mm above the base, a triangular window,
# and two 30 mm tabs glued into slots in the base. The base is 200 x 100 mm, r10 corners, the
# stands 60 mm apart, the wheels 40 mm apart on the axle; "FUNFAIR" engraved filled along the front.

import "std/joints.aidl"

units mm
thickness 3 mm

ply = 3 mm
axle_h = 130 mm       # axle above the base's top
stand_gap = 60 mm     # stand to stand, centre to centre
wheel_gap = 40 mm     # wheel to wheel, centre to centre

def wheel() -> solid {
    rim = Shell(Circle(center=(0, 0), radius=90), -10)
    hub = Circle(center=(0, 0), radius=15)
    spoke = Rectangle(center=(47.5, 0), width=75, height=6)
    spokes = CircularPattern(spoke, 8, (0, 0))
    # FIX after the first valid program: the cabins only touched the rim (W0504, W0519); 2 mm into it
    cabin = Circle(center=(98, 0), radius=10)
    cabins = CircularPattern(cabin, 8, (0, 0))
    hole axle { c = Circle(center=(0, 0), diameter=6) }
    hole window { c = Circle(center=(98, 0), diameter=10) }
    windows = CircularPattern(window, 8, (0, 0))
}

def stand() -> solid {
    frame = Trapezoid(center=(0, 74), bottom_width=160, top_width=30, height=148)
    feet = tab_and_slot(part="tab", length=160 mm, thickness=3 mm, tabs=2, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole axle { c = Circle(center=(0, 133), diameter=6.5) }
    hole window { w = Triangle(center=(0, 60), base=80, height=70) }
    Fillet([frame.top_left, frame.top_right], 8)
}

assembly ride {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=200, height=100, corner_radius=10)
        back_slots = tab_and_slot(part="slot", length=160 mm, thickness=3 mm, tabs=2, tab=30 mm,
                                  screw=0, clearance=0.1 mm, cx=0 mm, cy=stand_gap / 2)
        front_slots = tab_and_slot(part="slot", length=160 mm, thickness=3 mm, tabs=2, tab=30 mm,
                                   screw=0, clearance=0.1 mm, cx=0 mm, cy=-stand_gap / 2)
        drawing name {
            t = Text("FUNFAIR", position=(0, -44), size=7, font="sans:Bold", fill=true)
        }
    }
    back_stand = stand()
    front_stand = stand()
    back_wheel = wheel()
    front_wheel = wheel()

    # 3D: the stands stand on the base (their tabs through it), the wheels on the axle between them
    Place(base, position=(0, 0, 0))
    Place(back_stand, rotation=(90 deg, 0, 0), position=(0, stand_gap / 2 + ply / 2, 0))
    Place(front_stand, rotation=(90 deg, 0, 0), position=(0, -stand_gap / 2 + ply / 2, 0))
    Place(back_wheel, rotation=(90 deg, 0, 0), position=(0, wheel_gap / 2 + ply / 2, ply + axle_h))
    Place(front_wheel, rotation=(90 deg, 0, 0), position=(0, -wheel_gap / 2 + ply / 2, ply + axle_h))

    # flat on the sheet
    Above(back_stand, base, gap=5)
    AlignLeft(back_stand, base)
    RightOf(front_stand, back_stand, gap=5)
    AlignBottom(front_stand, back_stand)
    # FIX after the first valid program: the back wheel lay over the front stand (W0511)
    Above(back_wheel, back_stand, gap=5)
    AlignLeft(back_wheel, back_stand)
    RightOf(front_wheel, back_wheel, gap=5)
    AlignBottom(front_wheel, back_wheel)

    assert back_wheel.rim.bb.width == 180 mm, "rim 180 mm across"
    assert len(back_wheel.spokes) == 8 and len(back_wheel.cabins) == 8, "8 spokes, 8 cabins"
    assert back_wheel.cabin.radius * 2 == 20 mm and back_wheel.window.c.diameter == 10 mm, "20 mm cabins, 10 mm windows"
    assert back_stand.axle.c.center.y - back_stand.frame.bb.bottom - ply == 130 mm, "axle 130 mm above the base"
    assert axle_h > back_wheel.bb.height / 2, "the wheel clears the base"
    assert base.back_slots.bb.center_y - base.front_slots.bb.center_y == 60 mm, "stands 60 mm apart"
    assert back_stand.frame.bb.width == 160 mm, "stand 160 mm wide at the foot"
}
