# Request (camping): a flat-pack stand that lifts our 19 litre water jug (300 x 300 base, tap
# at the front) off the camp table so a mug fits under the tap. 6 mm ply, no glue, no screws:
# four 340 x 200 panels that slot together in a # by cross halvings, the crossings 280 mm
# apart (centre to centre). Front and back are slotted from the top, the sides from the bottom,
# each 100 deep. Every panel has a 200 x 60 half-oval arch cut from its bottom edge so it
# stands on two feet; the sides a 100 x 30 hand slot centred 150 up; the front "CAMP WATER"
# engraved filled, 20 mm letters, centred 140 up.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
L = 340 mm
H = 200 mm
span = 280 mm

def long_panel(label="") -> solid {
    body = Rectangle(bottom_left=(-L / 2, 0), width=L, height=H)
    hole arch { e = Ellipse(center=(0, 0), rx=100, ry=60) }
    s1 = cross_halving(depth=H / 2, thickness=T, cx=-span / 2, cy=H)
    s2 = cross_halving(depth=H / 2, thickness=T, cx=span / 2, cy=H)
    if label != "" {
        drawing name {
            t = Text(label, position=(0, 140), size=20, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    Rigid(self)
}

def short_panel() -> solid {
    body = Rectangle(bottom_left=(-L / 2, 0), width=L, height=H)
    hole arch { e = Ellipse(center=(0, 0), rx=100, ry=60) }
    s1 = cross_halving(depth=H / 2, thickness=T, rotation=180 deg, cx=-span / 2, cy=0)
    s2 = cross_halving(depth=H / 2, thickness=T, rotation=180 deg, cx=span / 2, cy=0)
    hole grip { s = Slot(center=(0, 150), length=100, width=30) }
    Rigid(self)
}

assembly jug_stand {
    front = long_panel(label="CAMP WATER")
    back = long_panel()
    left = short_panel()
    right = short_panel()

    # on the sheet: a 2 x 2 grid
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Below(left, front, gap=10)
    AlignLeft(left, front)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    # in 3D: x across, y front to back, z up; the panels' middles on the 280 square
    Place(front, position=(0, -span / 2 + T / 2, 0), face="front", up="up")
    Place(back, position=(0, span / 2 - T / 2, 0), face="back", up="up")
    Place(left, position=(-span / 2 + T / 2, 0, 0), face="left", up="up")
    Place(right, position=(span / 2 - T / 2, 0, 0), face="right", up="up")

    assert front.body.bb.width == 340 mm and front.body.bb.height == 200 mm, "panels 340 x 200"
    assert front.s2.cut.bb.center_x - front.s1.cut.bb.center_x == 280 mm, "crossings 280 apart"
    assert left.s2.cut.bb.center_x - left.s1.cut.bb.center_x == 280 mm, "crossings 280 apart"
    assert front.s1.cut.bb.height == 100 mm and left.s1.cut.bb.height == 100 mm, "100 deep"
    assert front.arch.e.rx * 2 == 200 mm and front.arch.e.ry == 60 mm, "200 x 60 arch"
    assert front.name.t.position.y - front.body.bb.bottom == 140 mm, "label 140 up"
}
