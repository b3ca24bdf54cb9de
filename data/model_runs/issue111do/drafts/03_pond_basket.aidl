# Request: a planting basket for a water lily in the garden pond, cut from 3 mm acrylic
# (it sinks) and solvent-glued. Open-top finger-jointed box 200 x 200 mm, 120 mm tall
# (outside), 15 mm fingers. Water must flow through every face: the front and back have a
# honeycomb of 12 mm holes (4 rows of 9, 18 mm apart, rows 16 mm apart, every second row
# shifted half a step), a 60 x 14 mm handle slot centred 18 mm below the top edge, and the
# plant's name "NYMPHAEA" engraved in single strokes (6 mm) between the holes and the
# handle; the two sides have a honeycomb of 12 mm holes (11 rows of 5); the bottom a
# square grid of 10 mm holes (9 x 9, 20 mm apart).

units mm
thickness 3 mm
import "std/joints.aidl"

def wall_holes() -> hole {
    # coordinates from the wall's bottom-left corner
    for r in range(4) {
        for k in range(9) {
            c = Circle(center=(23.5 + k * 18 + (9 if r % 2 == 1 else 0), 20 + r * 16), diameter=12)
        }
    }
    handle = Slot(center=(100, 102), length=60, width=14)
}

assembly pond_basket {
    box = finger_box(length=200 mm, depth=200 mm, height=120 mm, thickness=3 mm,
                     finger=15 mm, closed=false, outside=true)

    front_holes = wall_holes()
    Rigid(front_holes)
    At(front_holes.c[0][0].center, box.front.outline.bottom_left, dx=23.5, dy=20)
    CutInto(front_holes, box.front)

    back_holes = wall_holes()
    Rigid(back_holes)
    At(back_holes.c[0][0].center, box.back.outline.bottom_left, dx=23.5, dy=20)
    CutInto(back_holes, box.back)

    drawing front_name {
        t = Text("NYMPHAEA", position=(0, 0), size=6)
    }
    AlignCenterX(front_name.t.position, box.front.outline)
    front_name.t.position.y == box.front.outline.bb.bottom + 83 mm
    CutInto(front_name, box.front)

    # sides: 120 wide in x (their top edge outward), 200 tall in y
    hole left_hole { c = Circle(center=(0, 0), diameter=12) }
    left_grid = GridPattern(left_hole, 11, 5, col_spacing=18, row_spacing=16, stagger=true)
    At(left_hole.c.center, box.left.outline.bottom_left, dx=19.5, dy=20)
    CutInto(left_hole, box.left)

    hole right_hole { c = Circle(center=(0, 0), diameter=12) }
    right_grid = GridPattern(right_hole, 11, 5, col_spacing=18, row_spacing=16, stagger=true)
    At(right_hole.c.center, box.right.outline.bottom_left, dx=19.5, dy=20)
    CutInto(right_hole, box.right)

    hole floor_hole { c = Circle(center=(0, 0), diameter=10) }
    floor_grid = GridPattern(floor_hole, 9, 9, spacing=20)
    At(floor_hole.c.center, box.bottom.outline.bottom_left, dx=20, dy=20)
    CutInto(floor_hole, box.bottom)

    # the request's numbers
    assert box.front.outline.width == 200 mm and box.front.outline.height == 120 mm, "front 200 x 120"
    assert box.left.outline.height == 200 mm, "200 deep"
    assert len(front_holes.c) * len(front_holes.c[0]) == 36, "4 rows of 9"
    assert front_holes.c[0][0].diameter == 12 mm, "12 mm holes"
    assert box.front.outline.bb.top - front_holes.handle.center.y == 18 mm, "handle 18 below the top"
    assert front_holes.handle.length == 60 mm and front_holes.handle.width == 14 mm, "handle 60 x 14"
    assert len(left_grid) == 55, "11 rows of 5"
    assert len(floor_grid) == 81, "9 x 9"
    assert floor_hole.c.diameter == 10 mm, "10 mm floor holes"
    # holes stay clear of the 3 mm finger zone round each wall
    assert front_holes.bb.left - box.front.outline.bb.left >= 6 mm, "front holes clear the fingers"
    assert box.front.outline.bb.right - front_holes.bb.right >= 6 mm, "front holes clear the fingers"
    assert front_holes.handle.bb.bottom - (front_holes.c[3][0].center.y + 6 mm) >= 3 mm, "web under the handle"
}
