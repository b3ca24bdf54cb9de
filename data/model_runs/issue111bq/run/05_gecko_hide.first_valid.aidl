# Request: a hide for a leopard gecko's vivarium, 3 mm birch ply. A half-round tunnel 200 mm
# long whose roof is one living-hinge band (inside radius 70 mm, so 140 wide and 70 high
# inside) bent over two half-round end walls; the band's long edges go into a 170 x 210 base
# with three 30 mm tabs each, and each end wall stands in the base on two 20 mm tabs (slots
# 0.1 mm clearance). The front wall has a 50 wide x 40 high round-topped door (r20 top
# corners) over an 8 mm sill that keeps the substrate in; the back wall is closed. The
# gecko's name "SPIKE" is engraved over the door, 7 mm letters.
units mm
thickness 3 mm
import "std/joints.aidl"
import "std/plates.aidl"

T = 3 mm
R = 70 mm             # the roof's inside radius = the end walls' radius
LEN = 200 mm
BEND_W = pi * (R + T / 2)    # the band's bent width on the sheet
BAND_W = BEND_W + 2 * T       # plus a tab's length at each edge
CL = 0.1 mm

def end_wall() -> solid {
    # x across, y up: the tabs' tips at y = 0 (the base's underside), the base's top at y = T
    dome = Sector(center=(0, T), radius=R, start_angle=0, end_angle=180)
    strip = Rectangle(bottom_left=(-R, 0), width=2 * R, height=T)
    tabs = tab_and_slot(part="tab", length=2 * R, thickness=T, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
}

assembly gecko_hide {
    solid base {
        plate = Rectangle(center=(0, LEN / 2), width=170, height=210)
        front_slots = tab_and_slot(part="slot", length=2 * R, thickness=T, tabs=2, tab=20 mm,
                                   screw=0, clearance=CL, cx=0, cy=T / 2)
        back_slots = tab_and_slot(part="slot", length=2 * R, thickness=T, tabs=2, tab=20 mm,
                                  screw=0, clearance=CL, cx=0, cy=LEN - T / 2)
        roof_l = tab_and_slot(part="slot", length=LEN, thickness=T, tabs=3, tab=30 mm, screw=0,
                              clearance=CL, rotation=90 deg, cx=-(R + T / 2), cy=LEN / 2)
        roof_r = tab_and_slot(part="slot", length=LEN, thickness=T, tabs=3, tab=30 mm, screw=0,
                              clearance=CL, rotation=90 deg, cx=R + T / 2, cy=LEN / 2)
    }

    front = end_wall()
    back = end_wall()
    hole door {
        d = RoundedRectangle(bottom_left=(-25, T + 8), width=50, height=40,
                             corner_radii=[20, 20, 0, 0])
    }
    CutInto(door, front)
    AlignCenterX(door, front.dome)
    door.d.bb.bottom == front.strip.bb.top + 8 mm
    drawing name {
        word = Text("SPIKE", position=(0, 0), size=7, valign="middle")
    }
    CutInto(name, front)
    AlignCenterX(name, front.dome)
    name.word.position.y == door.d.bb.top + 9 mm

    # the roof band: x across the bend, y along the tunnel; the tabs' tips at x = 0 and BAND_W
    solid roof {
        band = Rectangle(bottom_left=(0, 0), width=BAND_W, height=LEN)
        hinge = living_hinge(width=BEND_W, height=LEN, pitch=2.5 mm, cut=15 mm, bridge=3 mm,
                             cx=BAND_W / 2, cy=LEN / 2)
        tabs_l = tab_and_slot(part="tab", length=LEN, thickness=T, tabs=3, tab=30 mm, screw=0,
                              rotation=90 deg, cx=0, cy=LEN / 2)
        tabs_r = tab_and_slot(part="tab", length=LEN, thickness=T, tabs=3, tab=30 mm, screw=0,
                              rotation=-90 deg, cx=BAND_W, cy=LEN / 2)
    }

    # on the sheet
    RightOf(front, base, gap=8)
    AlignTop(front, base)
    RightOf(back, base, gap=8)
    Below(back, front, gap=8)
    Below(roof, base, gap=8)
    AlignLeft(roof, base)

    # in 3D: x across, y along the tunnel (front at 0), z up; the base's underside at z = 0
    Place(base, position=(0, 0, 0))
    Place(front, rotation=(90 deg, 0, 0), position=(0, T, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, LEN, 0))
    # the band's left edge stands in the base at x = -R - T, its top face inward
    Place(roof, rotation=(180 deg, -90 deg, 0), position=(-R - T, LEN, 0))
    Bend(roof, at=BAND_W / 2, angle=180 deg, radius=R)

    assert front.dome.radius == 70 mm, "inside radius 70"
    assert roof.band.bb.height == 200 mm, "200 long"
    assert base.plate.bb.width == 170 mm and base.plate.bb.height == 210 mm, "base 170 x 210"
    assert door.d.bb.width == 50 mm and door.d.bb.height == 40 mm, "door 50 x 40"
    assert door.d.bb.bottom - front.strip.bb.top == 8 mm, "8 mm sill"
    assert name.word.size == 7 mm, "7 mm letters"
}
