# Request (bathroom): a caddy by the basin for a 500 ml mouthwash bottle and two rinse
# cups, in 3 mm acrylic: a closed finger-jointed box 270 x 95 mm, 70 mm tall (10 mm
# fingers). Its top is a deck with a 100 x 66 mm opening (10 mm corner radius) for the
# bottle on the left and two 60 mm round holes for the cups to the right, the three
# openings in a row along the length, centred front to back, with equal 11 mm gaps
# between them and to the inside of the walls. The bottom has 18 drain holes of 6 mm
# (2 rows of 9, 26 mm apart along, 30 mm apart across), centred. RINSE is engraved
# on the front in bold sans letters 16 mm tall, filled, centred.

import "std/joints.aidl"

thickness 3 mm

box_l = 270 mm
box_d = 95 mm
box_h = 70 mm
gap = 11 mm
bottle_w = 100 mm
bottle_d = 66 mm
cup_d = 60 mm

# centres along the length, from the inside of the left wall
inner_half = box_l / 2 - 3 mm
bottle_x = -inner_half + gap + bottle_w / 2
cup1_x = bottle_x + bottle_w / 2 + gap + cup_d / 2
cup2_x = cup1_x + cup_d + gap

assembly caddy {
    box = finger_box(length=box_l, depth=box_d, height=box_h, thickness=3 mm, finger=10 mm,
                     closed=true)

    hole openings {
        bottle = RoundedRectangle(center=(bottle_x, 0), width=bottle_w, height=bottle_d,
                                  corner_radius=10 mm)
        cup1 = Circle(center=(cup1_x, 0), diameter=cup_d)
        cup2 = Circle(center=(cup2_x, 0), diameter=cup_d)
    }
    CenterInside(openings, box.lid)
    CutInto(openings, box.lid)

    hole drains {
        d = Circle(center=(0, 0), diameter=6 mm)
        g = GridPattern(d, 2, 9, (26 mm, 30 mm))
    }
    CenterInside(drains, box.bottom)
    CutInto(drains, box.bottom)

    drawing word {
        t = Text("RINSE", position=(0, 0), size=16 mm, font="sans:Bold", fill=true,
                 valign="middle")
    }
    CenterInside(word, box.front)
    CutInto(word, box.front)

    assert box.lid.bb.width == 270 mm, "270 mm long"
    assert box.lid.bb.height == 95 mm, "95 mm deep"
    assert box.front.bb.height == 70 mm, "70 mm tall"
    assert openings.bottle.width == 100 mm and openings.bottle.height == 66 mm, "bottle opening"
    assert openings.cup1.diameter == 60 mm and openings.cup2.diameter == 60 mm, "cup holes"
    assert openings.cup1.bb.left - openings.bottle.bb.right == 11 mm, "11 mm gap"
    assert openings.cup2.bb.left - openings.cup1.bb.right == 11 mm, "11 mm gap"
    assert openings.bottle.bb.left - box.lid.bb.left == 3 mm + 11 mm, "11 mm inside the wall"
    assert box.lid.bb.right - openings.cup2.bb.right == 3 mm + 11 mm, "11 mm inside the wall"
    assert len(drains.g) == 18, "18 drain holes"
}
