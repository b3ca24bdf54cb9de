# Request (pets): an enclosure for our Mexican red-knee tarantula, 3 mm clear acrylic,
# finger-jointed (15 mm fingers), 300 x 200 x 200 mm outside. Cross-ventilation high up on
# both sides: on each side a staggered grid of 4 mm holes, 3 columns by 12 rows, 10 mm apart,
# its top column 15 mm below the top edge. The lid: a 50 mm feeding hatch, its centre 70 mm
# from the lid's left edge, with a swing cover (a 62 mm disc and a 14 mm ear, pivot 40 mm from
# the hatch centre on an M3 screw: 3.2 mm holes in the cover and the lid); on the lid's right
# half a 5 x 10 grid of 4 mm vent holes, 10 mm apart, 25 mm in from the right edge. On the
# front, 12 mm below its top edge (above the deep substrate), engrave "BRACHYPELMA HAMORII"
# 7 mm tall and under it "MEXICAN RED KNEE" 5 mm tall. "FEED" engraved on the cover.

import "std/joints.aidl"

units mm
thickness 3 mm

param t = 3 mm, min = 2, max = 6

assembly enclosure {
    box = finger_box(length=300 mm, depth=200 mm, height=200 mm, thickness=t, finger=15 mm)

    # side vents: a staggered grid near each side's top edge (the left's top edge is at -x)
    hole left_vents {
        v = Circle(center=(0, 0), diameter=4)
        g = GridPattern(v, 12, 3, (10, 10), stagger=true)
    }
    hole right_vents {
        v = Circle(center=(0, 0), diameter=4)
        g = GridPattern(v, 12, 3, (10, 10), stagger=true)
    }
    left_vents.v.center.x == box.left.bb.left + 15 mm
    AlignCenterY(left_vents, box.left)
    CutInto(left_vents, box.left)
    right_vents.bb.right == box.right.bb.right - 15 mm + 2 mm
    AlignCenterY(right_vents, box.right)
    CutInto(right_vents, box.right)

    # the lid: feeding hatch with the cover's pivot, and vents on its right half
    hole hatch {
        c = Circle(center=(-80, 410), diameter=50)
        pivot = Circle(center=(-40, 410), diameter=3.2)
    }
    hatch.c.center.x == box.lid.bb.left + 70 mm
    hatch.c.center.y == box.lid.bb.center_y
    Rigid(hatch)
    CutInto(hatch, box.lid)

    hole lid_vents {
        v = Circle(center=(0, 0), diameter=4)
        g = GridPattern(v, 5, 10, (10, 10))
    }
    lid_vents.bb.right == box.lid.bb.right - 25 mm
    AlignCenterY(lid_vents, box.lid)
    CutInto(lid_vents, box.lid)

    # the front's label, high up
    drawing label {
        species = Text("BRACHYPELMA HAMORII", (0, 0), size=7)
        common = Text("MEXICAN RED KNEE", (0, -11), size=5)
    }
    Rigid(label)
    AlignCenterX(label, box.front)
    label.bb.top == box.front.bb.top - 12 mm
    CutInto(label, box.front)

    # the swing cover over the hatch, turning on an M3 screw
    solid cover {
        body = Hull(Circle(center=(0, 0), diameter=62), Circle(center=(40, 0), diameter=14))
        hole pin { c = Circle(center=(40, 0), diameter=3.2) }
        drawing word { w = Text("FEED", (0, 0), size=8, valign="middle") }
    }
    RightOf(cover, box, gap=10)
    AlignTop(cover, box)
    Place(cover, on=box.lid, position=(-80, 410, t))
}

assert abs(enclosure.box.bottom.bb.width - 300 mm) < 0.01 mm, "300 mm long outside"
assert abs(enclosure.box.front.bb.height - 200 mm) < 0.01 mm, "200 mm tall outside"
assert abs(enclosure.box.left.bb.height - 200 mm) < 0.01 mm, "200 mm deep outside"
assert len(enclosure.left_vents.g) == 36 and len(enclosure.right_vents.g) == 36, "3 x 12 side vents"
assert len(enclosure.lid_vents.g) == 50, "5 x 10 lid vents"
assert abs(enclosure.hatch.c.center.x - enclosure.box.lid.bb.left - 70 mm) < 0.01 mm, "hatch 70 mm from the lid's left edge"
assert abs(distance(enclosure.hatch.c.center, enclosure.hatch.pivot.center) - 40 mm) < 0.01 mm, "pivot 40 mm from the hatch"
assert abs(enclosure.hatch.c.center.x - (-80 mm)) < 0.01 mm and abs(enclosure.hatch.c.center.y - 410 mm) < 0.01 mm,
    "the cover's 3D place is the hatch"
assert distance(enclosure.hatch, enclosure.lid_vents) >= 10 mm, "hatch clear of the lid vents"
assert abs(enclosure.box.lid.bb.right - enclosure.lid_vents.bb.right - 25 mm) < 0.01 mm, "lid vents 25 mm in"
assert abs(enclosure.box.front.bb.top - enclosure.label.bb.top - 12 mm) < 0.01 mm, "label 12 mm below the top"
assert enclosure.label.bb.width < 300 mm - 40 mm, "label fits the front"
