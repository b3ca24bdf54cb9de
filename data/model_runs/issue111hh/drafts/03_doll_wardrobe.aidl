# Request (toys): a wardrobe for an 11.5-inch fashion doll, 3 mm birch ply, glued tab and slot.
# - Two sides 120 mm deep x 300 mm tall, each with an arched cut-out at the floor (80 mm wide,
#   12 mm high) leaving a foot at the front and back, and a 6.2 mm hole for a 6 mm dowel
#   hanging rail, 60 mm from the front and 255 mm up.
# - A top and a bottom board, 200 mm across the outside of the sides, reaching from the front
#   edge to the back panel; each with two 30 mm tabs at each end into the sides. The top board's
#   top face 3 mm below the top of the sides; the bottom board's middle 30 mm above the floor.
# - A back panel standing 6 mm in from the sides' back edges (its middle), from the floor to
#   the sides' top, with three 40 mm tabs on each edge into the sides, and a crest above the
#   sides: a half-ellipse 194 mm wide and 60 mm high with a heart cut out and the doll's name
#   LUNA engraved filled in 10 mm bold letters under the heart.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
depth = 120 mm
tall = 300 mm
across = 200 mm
back_in = 6 mm                  # the back panel's middle, in from the sides' back edges
shelf_d = depth - back_in - t / 2

def side() -> solid {
    body = Rectangle(bottom_left=(0, 0), width=depth, height=tall)
    hole arch {
        e = Ellipse(center=(depth / 2, 0), rx=40, ry=12)
    }
    hole rail {
        c = Circle(center=(60, 255), diameter=6.2)
    }
    top_slot = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2, tab=30, screw=0,
                            cx=shelf_d / 2, cy=tall - t - t / 2)
    bottom_slot = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2, tab=30, screw=0,
                               cx=shelf_d / 2, cy=30)
    back_slot = tab_and_slot(part="slot", length=tall, thickness=t, tabs=3, tab=40, screw=0,
                             rotation=90 deg, cx=depth - back_in, cy=tall / 2)
}

def shelf() -> solid {
    body = Rectangle(center=(0, 0), width=across, height=shelf_d)
    left = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=30, screw=0,
                        rotation=90 deg, cx=-across / 2, cy=0)
    right = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=30, screw=0,
                         rotation=-90 deg, cx=across / 2, cy=0)
}

assembly wardrobe {
    left_side = side()
    right_side = side()
    top = shelf()
    bottom = shelf()

    solid back {
        body = Rectangle(center=(0, tall / 2), width=across, height=tall)
        crest = Ellipse(center=(0, tall), rx=across / 2 - t, ry=60)
        left = tab_and_slot(part="tab", length=tall, thickness=t, tabs=3, tab=40, screw=0,
                            rotation=90 deg, cx=-across / 2, cy=tall / 2)
        right = tab_and_slot(part="tab", length=tall, thickness=t, tabs=3, tab=40, screw=0,
                             rotation=-90 deg, cx=across / 2, cy=tall / 2)
        hole heart {
            l = Hull(Circle(center=(-8, tall + 35 + 5), radius=9), Point(0, tall + 35 - 16))
            r = Hull(Circle(center=(8, tall + 35 + 5), radius=9), Point(0, tall + 35 - 16))
        }
        drawing name {
            n = Text("LUNA", position=(0, tall + 4), size=10, font="sans:Bold", fill=true)
        }
    }

    RightOf(right_side, left_side, gap=10)
    AlignBottom(right_side, left_side)
    RightOf(back, right_side, gap=10)
    AlignBottom(back, right_side)
    RightOf(top, back, gap=10)
    AlignTop(top, back)
    Below(bottom, top, gap=10)
    AlignLeft(bottom, top)

    assert left_side.body.bb.width == 120 mm and left_side.body.bb.height == 300 mm
    assert left_side.arch.e.rx * 2 == 80 mm and left_side.arch.e.ry == 12 mm
    assert left_side.rail.c.center.x - left_side.body.bb.left == 60 mm
    assert left_side.rail.c.center.y - left_side.body.bb.bottom == 255 mm
    assert left_side.body.bb.top - left_side.top_slot.slot[0].bb.top == 3 mm
    assert left_side.bottom_slot.slot[0].bb.center_y - left_side.body.bb.bottom == 30 mm
    assert left_side.body.bb.right - left_side.back_slot.slot[0].bb.center_x == 6 mm
    assert top.body.bb.width == 200 mm
    assert back.crest.bb.top - back.body.bb.top == 60 mm
    assert back.crest.bb.width == 194 mm
    assert distance(back.name, back.heart) >= 2 mm
    assert back.name.bb.bottom >= back.body.bb.top + 2 mm, "the name shows above the sides"
    assert distance(left_side.rail, left_side.top_slot) >= 10 mm
}
