# Request: three stacking sorting trays for the pieces of a 1000-piece jigsaw
# puzzle, 3 mm birch ply. Each is an open finger-jointed tray 240 x 170 x 25 mm
# outside with 10 mm fingers. Each short side has a finger-pull notch in its top
# edge, 40 mm wide and 12 mm deep with R6 corners, to lift the tray off the one
# below. The front of each is engraved, filled, in bold sans with 10 mm capitals,
# centred: EDGES, SKY and REST. The trays stack straight on top of each other.

import "std/joints.aidl"

thickness 3 mm

param tray_l = 240 mm, min = 150 mm, max = 400 mm
param tray_w = 170 mm, min = 100 mm, max = 300 mm
param tray_h = 25 mm, min = 20 mm, max = 60 mm
notch_w = 40 mm
notch_d = 12 mm

def sorting_tray(label="EDGES") -> assembly {
    box = finger_box(length=tray_l, depth=tray_w, height=tray_h, thickness=3 mm,
                     finger=10 mm, closed=false)

    # the engraved name, centred on the front
    drawing name {
        t = Text(label, position=(0, 0), size=10, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(name, box.front)
    name.t.position.y == box.front.outline.center.y
    CutInto(name, box.front)

    # finger-pull notches: the sides lie with their top edge outward
    # (the left's at -x, the right's at +x)
    hole grip_l {
        g = RoundedRectangle(center=(0, 0), width=2 * notch_d, height=notch_w, corner_radius=6)
    }
    AlignCenterY(grip_l, box.left.outline)
    grip_l.g.center.x == box.left.outline.bb.left
    CutInto(grip_l, box.left)

    hole grip_r {
        g = RoundedRectangle(center=(0, 0), width=2 * notch_d, height=notch_w, corner_radius=6)
    }
    AlignCenterY(grip_r, box.right.outline)
    grip_r.g.center.x == box.right.outline.bb.right
    CutInto(grip_r, box.right)
}

assembly trays {
    edges = sorting_tray(label="EDGES")
    sky = sorting_tray(label="SKY")
    rest = sorting_tray(label="REST")

    # laid out flat side by side
    RightOf(sky, edges, gap=10)
    AlignBottom(sky, edges)
    RightOf(rest, sky, gap=10)
    AlignBottom(rest, sky)

    # assembled: stacked, each on the walls of the one below
    Place(sky, position=(0, 0, 25))
    Place(rest, position=(0, 0, 50))

    assert edges.box.front.outline.width == 240 mm, "240 long"
    assert edges.box.left.outline.height == 170 mm, "170 deep"
    assert edges.box.front.outline.height == 25 mm, "25 tall"
    assert edges.grip_l.g.bb.right - edges.box.left.outline.bb.left == 12 mm, "notch 12 deep"
    assert edges.grip_l.g.bb.height == 40 mm, "notch 40 wide"
    assert rest.grip_r.g.bb.height == 40 mm, "notch 40 wide"
    assert distance(edges.name, edges.box.front.outline.bottom) >= 3 mm, "name clear of the bottom joint"
}
