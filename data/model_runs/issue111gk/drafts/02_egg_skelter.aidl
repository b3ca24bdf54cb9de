# Request: a zigzag egg rack for the kitchen counter, 6 mm ply. Two side panels 260 mm long
# and 230 mm tall (top corners R20, a 180 x 10 mm arch under each so it stands on two feet),
# 64 mm apart inside, joined by three sloping shelves (3 degrees, alternating) on which the
# eggs roll: the top shelf 180 long from the right end down to the left, the middle one 180
# long from the left end down to the right, the bottom one 240 long down to the left. Each
# shelf has three 30 mm tabs per side glued into slots (0.2 mm clearance) in the sides.
# Eggs up to 45 mm across: 50 mm clear under every shelf, 50 mm drop openings at the turns.
# Three 8 mm dowels (holes 8.2 mm) stop the eggs at the turns and at the bottom.
# "EGGS" in filled 16 mm bold letters engraved near the top of each side, reading from outside.

import "std/joints.aidl"

thickness 6 mm

slope = 3 deg
inner = 64 mm
# shelf centre lines in the side panel: (centre x, centre y, +1 rising to +x / -1 falling)
y1 = 162 mm
y2 = 96 mm
y3 = 30 mm

def fx(x, flip) = 260 mm - x if flip else x
# height of a shelf's centre line at x
def sy(yc, xc, sgn, x) = yc + sgn * (x - xc) * tan(slope)

def shelf(length=180 mm) -> solid {
    body = Rectangle(center=(0, 0), width=length, height=inner + 2 * 6 mm)
    near = tab_and_slot(part="tab", length=length, thickness=6 mm, tabs=3, tab=30 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=-(inner / 2 + 6 mm))
    far = tab_and_slot(part="tab", length=length, thickness=6 mm, tabs=3, tab=30 mm,
                       screw=0, rotation=0 deg, cx=0 mm, cy=inner / 2 + 6 mm)
}

# a side panel; flip=true: the far side, its slots and holes mirrored, its lettering not
def side(flip=false) -> solid {
    body = RoundedRectangle(bottom_left=(0, 0), width=260, height=230,
                            corner_radii=[20, 20, 0, 0])
    top_slots = tab_and_slot(part="slot", length=180 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, clearance=0.2 mm,
                             rotation=(-slope if flip else slope),
                             cx=fx(160 mm, flip), cy=y1)
    mid_slots = tab_and_slot(part="slot", length=180 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, clearance=0.2 mm,
                             rotation=(slope if flip else -slope),
                             cx=fx(100 mm, flip), cy=y2)
    low_slots = tab_and_slot(part="slot", length=240 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, clearance=0.2 mm,
                             rotation=(-slope if flip else slope),
                             cx=fx(130 mm, flip), cy=y3)
    hole dowels {
        a = Circle(center=(fx(12 mm, flip), 178), diameter=8.2)
        b = Circle(center=(fx(248 mm, flip), 112), diameter=8.2)
        c = Circle(center=(fx(20 mm, flip), 36), diameter=8.2)
    }
    hole arch { e = Ellipse(center=(130, 0), rx=90, ry=10) }
    drawing word {
        t = Text("EGGS", position=(130, 203), size=16, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

assembly egg_rack {
    front = side()
    back = side(flip=true)
    top = shelf(length=180 mm)
    mid = shelf(length=180 mm)
    low = shelf(length=240 mm)

    # on the sheet
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Below(top, front, gap=10)
    AlignLeft(top, front)
    RightOf(mid, top, gap=10)
    AlignTop(mid, top)
    Below(low, top, gap=10)
    AlignLeft(low, top)

    # assembled: the rack runs along x, the front side's inner face at y = -32
    Place(front, position=(0, -inner / 2, 0), face="front", up="up")
    Place(back, position=(260, inner / 2, 0), face="back", up="up")
    # FIX after the first valid program: position is the bottom face's (0, 0); with the
    # shelf tilted, the mid-plane's centre is 3 mm along the tilted normal from it, not
    # straight up (W0517: the shelves sat 0.16 mm off along x, their tabs into the slot ends)
    Place(top, position=(160 mm + 3 mm * sin(slope), 0, y1 - 3 mm * cos(slope)),
          rotation=(0, -slope, 0))
    Place(mid, position=(100 mm - 3 mm * sin(slope), 0, y2 - 3 mm * cos(slope)),
          rotation=(0, slope, 0))
    Place(low, position=(130 mm + 3 mm * sin(slope), 0, y3 - 3 mm * cos(slope)),
          rotation=(0, -slope, 0))

    assert front.body.bb.width == 260 mm and front.body.bb.height == 230 mm,
        "sides 260 x 230"
    assert top.body.bb.height - 2 * 6 mm == 64 mm, "64 mm between the sides"
    assert top.body.bb.width == 180 mm and mid.body.bb.width == 180 mm, "two 180 mm shelves"
    assert low.body.bb.width == 240 mm, "a 240 mm bottom shelf"
    # 50 mm clear under the shelf above, where the two come closest
    assert (sy(y1, 160 mm, 1, 70 mm) - 3 mm) - (sy(y2, 100 mm, -1, 70 mm) + 3 mm) >= 50 mm,
        "an egg passes under the top shelf"
    assert (sy(y2, 100 mm, -1, 190 mm) - 3 mm) - (sy(y3, 130 mm, 1, 190 mm) + 3 mm) >= 50 mm,
        "an egg passes under the middle shelf"
    # 50 mm drop openings between a shelf's low end and the dowel beyond it
    assert (160 mm - 90 mm) - (12 mm + 4.1 mm) >= 50 mm, "top turn opening"
    assert (248 mm - 4.1 mm) - (100 mm + 90 mm) >= 50 mm, "middle turn opening"
    assert front.arch.e.rx * 2 == 180 mm and front.arch.e.ry == 10 mm, "180 x 10 arch"
    assert front.word.t.size == 16 mm, "16 mm letters"
}
