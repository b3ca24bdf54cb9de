# Request: a window perch for our cat, 6 mm birch ply, cut on a 600 x 400 mm bed. The
# platform is 700 x 260 mm, its two front corners rounded r40; it is too wide for the bed, so
# it is cut as two halves joined in the middle by a sliding dovetail (3 tails, 12 mm deep,
# 10 degrees, 0.1 mm clearance in the sockets). Its back 120 mm rests on the window sill and
# is screwed down with four M4 flat-heads (4.5 mm holes countersunk 9 mm, 40 mm from the back
# edge, at 100 and 300 mm either side of the middle). Under the 140 mm overhang two curved
# brackets, 500 mm apart (at 250 mm either side of the middle), bear on the wall under the
# sill: each 130 mm along the platform and 180 mm down the wall, the inside an elliptical
# sweep leaving a 30 mm foot on the wall and a 30 mm deep front end, glued into the platform
# with two 25 mm tenons. "MILO" engraved filled, 40 mm bold, on the left half's overhang, and
# a trail of three filled paw prints on the right half's overhang.

import "std/joints.aidl"

thickness 6 mm

HALF = 350 mm
DEPTH = 260 mm
TAIL = 12 mm
BX = 250 mm          # brackets' middle planes at +-BX
WALL_Y = 10 mm       # the sill's front edge (the wall face) on the platform: 120 mm from the back
REACH = 130 mm       # bracket length along the platform
DROP = 180 mm        # bracket length down the wall

def bracket() -> solid {
    # flat: x = distance from the wall, y = height with the platform's underside at 0;
    # the tenons' tips on y = 6 (through the platform)
    body = Rectangle(bottom_left=(0, -180), width=130, height=186)
    hole sweep { e = Ellipse(center=(130, -180), rx=100, ry=150, overrun=true) }
    tenons = tab_and_slot(part="tab", length=130 mm, thickness=6 mm, tabs=2, tab=25 mm,
                          screw=0, cx=65 mm, cy=6 mm)
}

def paw() -> drawing {
    pad = Ellipse(center=(0, 0), rx=10, ry=8, fill=true)
    t1 = Ellipse(center=(-12, 10), rx=4, ry=5, fill=true)
    t2 = Ellipse(center=(-4.5, 16), rx=4, ry=5, fill=true)
    t3 = Ellipse(center=(4.5, 16), rx=4, ry=5, fill=true)
    t4 = Ellipse(center=(12, 10), rx=4, ry=5, fill=true)
}

assembly perch {
    solid left {
        # tails reach across the 12 mm band right of the joint line x = 0
        body = RoundedRectangle(bottom_left=(-350, -130), width=HALF + TAIL, height=DEPTH,
                                corner_radii=[0, 0, 0, 40])
        Fixed(body)
        tails = dovetail(part="tail", length=DEPTH, depth=TAIL, tails=3, angle=10 deg,
                         rotation=-90 deg, cx=0 mm, cy=0 mm)
        hole screw_a { c = Circle(center=(-300, 90), diameter=4.5) }
        hole screw_b { c = Circle(center=(-100, 90), diameter=4.5) }
        Countersink([screw_a, screw_b], diameter=9 mm)
        mortise = tab_and_slot(part="slot", length=REACH, thickness=6 mm, tabs=2, tab=25 mm,
                               screw=0, rotation=90 deg, cx=-BX, cy=WALL_Y - REACH / 2)
        drawing name {
            t = Text("MILO", position=(-160, -75), size=40, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    solid right {
        body = RoundedRectangle(bottom_left=(0, -130), width=HALF, height=DEPTH,
                                corner_radii=[0, 0, 40, 0])
        Fixed(body)
        sockets = dovetail(part="socket", length=DEPTH, depth=TAIL, tails=3, angle=10 deg,
                           clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
        hole screw_a { c = Circle(center=(100, 90), diameter=4.5) }
        hole screw_b { c = Circle(center=(300, 90), diameter=4.5) }
        Countersink([screw_a, screw_b], diameter=9 mm)
        mortise = tab_and_slot(part="slot", length=REACH, thickness=6 mm, tabs=2, tab=25 mm,
                               screw=0, rotation=90 deg, cx=BX, cy=WALL_Y - REACH / 2)
        first_paw = paw()
        # FIX after the first valid program: with Translate(first_paw, (110, -95)) the pattern's
        # two copies stayed at (45, 22) and (90, 44) from the paw as written (on the sill part,
        # by the dovetail), only the original moved; the original is placed by a constraint now
        trail = LinearPattern(first_paw, 3, (45, 22))
        first_paw.pad.center == (110, -95)
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # the sheet: halves side by side, brackets under them
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Below(left_bracket, left, gap=10)
    AlignLeft(left_bracket, left)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignTop(right_bracket, left_bracket)

    # 3D: the platform's underside on z = 0, the wall face on y = WALL_Y, brackets under it
    Place(left, position=(0, 0, 0))
    Place(right, position=(0, 0, 0))
    Place(left_bracket, rotation=(90 deg, 0, -90 deg), position=(-BX + 3 mm, WALL_Y, 0))
    Place(right_bracket, rotation=(90 deg, 0, -90 deg), position=(BX + 3 mm, WALL_Y, 0))

    # the request's numbers
    assert left.body.bb.width - TAIL + right.body.bb.width == 700 mm, "platform 700 wide"
    assert left.body.bb.height == 260 mm, "platform 260 deep"
    assert left.body.bb.width <= 400 mm and right.body.bb.width <= 400 mm, "halves fit the bed"
    assert left.screw_a.c.center.y - left.body.bb.bottom == 260 mm - 40 mm, "screws 40 from back"
    assert right.screw_b.c.center.x - right.body.bb.left == 300 mm, "screw 300 from the middle"
    assert left_bracket.body.bb.width == 130 mm and left_bracket.body.bb.height - 6 mm == 180 mm,
        "bracket 130 x 180"
    assert left.body.bb.top - WALL_Y - 120 mm == 0 mm, "120 mm on the sill"
    assert len(right.trail) == 3, "three paw prints"
    assert right.trail[2].pad.center.x - right.trail[0].pad.center.x == 90 mm, "a trail (FIX)"
    assert right.trail[2].bb.top < WALL_Y, "paws on the overhang (FIX)"
}
