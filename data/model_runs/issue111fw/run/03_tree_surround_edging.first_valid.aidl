# REQUEST (garden): a square scalloped edging to go round a young tree or a small herb bed,
# four identical panels of 6 mm HDPE sheet that slot together at the corners with cross
# halvings, no tools. Each panel is 400 mm long; above the soil line it is a band 75 mm tall
# whose top carries 4 round arches, each 85 mm wide and rising 20 mm (to 95 mm), side by side
# between 30 mm flat ends; below the soil line 3 pointed stakes, 40 mm wide and 60 mm long,
# at 100, 200 and 300 mm along. At 15 mm from the left end a halving slot comes down from the
# top, at 15 mm from the right end one comes up from the bottom, each half the 75 mm band
# (37.5 mm) deep and 6.3 mm wide (0.3 mm clearance), so each panel's right end locks into the
# next one's left end and the four make a square 370 mm between the panels' centre lines,
# the ends standing 15 mm past each corner. Shown assembled round the square.

units mm
import "std/joints.aidl"

t = 6 mm
thickness t

def panel() -> solid {
    band = Rectangle(corner=(0, 0), opposite=(400, 75))
    for i in range(4) {
        arch = Intersect(Circle(center=(30 + 42.5 + 85 * i, 95 - 55.15625), radius=55.15625),
                         Rectangle(corner=(30 + 85 * i, 70), opposite=(30 + 85 * (i + 1), 100)))
    }
    for k in range(3) {
        stake = Triangle(center=(100 + 100 * k, -30), base=40, height=60, rotation=180)
    }
    down = cross_halving(depth=37.5 mm, thickness=t, clearance=0.3 mm, cx=15 mm, cy=75 mm)
    up = cross_halving(depth=37.5 mm, thickness=t, clearance=0.3 mm, rotation=180 deg,
                       cx=385 mm, cy=0 mm)
}

assembly edging {
    front = panel()
    right = panel()
    back = panel()
    left = panel()
    # flat: stacked for cutting
    Above(right, front, gap=10)
    AlignLeft(right, front)
    Above(back, right, gap=10)
    AlignLeft(back, right)
    Above(left, back, gap=10)
    AlignLeft(left, back)

    # 3D: the panels' centre lines on x = 0, x = 370, y = 0, y = 370; z = 0 the soil line
    Place(front, position=(-15, 3, 0), face="front", up="up")
    Place(right, position=(367, -15, 0), face="right", up="up")
    Place(back, position=(385, 367, 0), face="back", up="up")
    Place(left, position=(3, 385, 0), face="left", up="up")
}

# the request's numbers
assert edging.front.band.bb.width == 400 mm, "panels 400 mm long"
assert edging.front.band.bb.height == 75 mm, "band 75 mm above the soil line"
assert len(edging.front.arch) == 4, "4 arches"
assert edging.front.arch[0].bb.width == 85 mm, "arches 85 mm wide"
assert abs(edging.front.arch[0].bb.top - 95 mm) < 0.01 mm, "arches rise to 95 mm"
assert edging.front.arch[0].bb.left == 30 mm and edging.front.arch[3].bb.right == 370 mm, "30 mm flat ends"
assert len(edging.front.stake) == 3, "3 stakes"
assert edging.front.stake[0].bb.height == 60 mm and edging.front.stake[0].bb.width == 40 mm, "stakes 40 x 60"
assert edging.front.down.depth + edging.front.up.depth == 75 mm, "the two halvings add up to the band"
assert edging.front.down.cut.bb.width == 6.3 mm, "slots 6.3 mm wide"
assert edging.front.down.cut.bb.center_x == 15 mm, "top slot 15 mm from the left end"
assert 400 mm - edging.front.up.cut.bb.center_x == 15 mm, "bottom slot 15 mm from the right end"
