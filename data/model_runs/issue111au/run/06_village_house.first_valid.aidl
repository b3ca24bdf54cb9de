# Request: a Christmas village house that goes over a tealight, 3 mm plywood,
# five parts. Footprint 80 x 60 mm, walls 70 mm to the eaves, the gables peaking
# 100 mm above the table. Front and back gable walls (80 wide) finger-jointed to
# the two side walls (60 deep), 10 mm fingers. The front has an arched door 16 mm
# wide and 28 mm tall opening at the bottom edge, and two four-pane windows
# 14 x 14 mm; the back has the two windows only; each gable has a round window
# 10 mm across; each side wall has one four-pane window in its middle. The roof
# is one panel that bends over the ridge on a living hinge 16 mm wide, overhangs
# 5 mm at the gables and 6 mm at the eaves, with engraved shingle courses.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

param ply = 3 mm, min = 2 mm, max = 4 mm
param length = 80 mm, min = 60 mm, max = 120 mm
param depth = 60 mm, min = 40 mm, max = 100 mm
param eaves = 70 mm, min = 50 mm, max = 100 mm
param ridge = 100 mm, min = 70 mm, max = 140 mm
param hinge_w = 16 mm, min = 10 mm, max = 30 mm

gable_h = ridge - eaves
rafter = sqrt((length / 2) ** 2 + gable_h ** 2)   # eave corner to ridge, along the slope
slope_w = rafter + 6 mm                            # one roof slope with its eave overhang
roof_w = 2 * slope_w + hinge_w
roof_l = depth + 2 * 5 mm

def four_pane(x=0 mm, y=0 mm) -> hole {
    # a 14 mm window: four 6 mm panes with 2 mm glazing bars
    p1 = Rectangle(center=(x - 4, y + 4), width=6, height=6)
    p2 = Rectangle(center=(x + 4, y + 4), width=6, height=6)
    p3 = Rectangle(center=(x - 4, y - 4), width=6, height=6)
    p4 = Rectangle(center=(x + 4, y - 4), width=6, height=6)
}

def gable_wall(door=1) -> solid {
    wall = finger_panel(width=length, height=eaves, thickness=ply, finger=10 mm,
                        bottom="flat", top="flat", left="fingers", right="fingers")
    gable = Triangle(center=(0, eaves / 2 + gable_h / 2), base=length, height=gable_h)
    hole round_window {
        c = Circle(center=(0, eaves / 2 + gable_h * 0.4), diameter=10)
    }
    win_l = four_pane(x=-length * 0.3, y=5 mm)
    win_r = four_pane(x=length * 0.3, y=5 mm)
    if door == 1 {
        hole doorway {
            leaf = Rectangle(center=(0, -eaves / 2 + 10), width=16, height=20)
            arch = Circle(center=(0, -eaves / 2 + 20), radius=8)
        }
    }
}

def side_wall() -> solid {
    wall = finger_panel(width=depth, height=eaves, thickness=ply, finger=10 mm,
                        bottom="flat", top="flat", left="slots", right="slots")
    win = four_pane(x=0 mm, y=5 mm)
}

assembly village_house {
    front = gable_wall(door=1)
    back = gable_wall(door=0)
    left = side_wall()
    right = side_wall()

    solid roof {
        panel = Rectangle(center=(0, 0), width=roof_w, height=roof_l)
        bend = living_hinge(width=hinge_w, height=roof_l, pitch=2 mm, cut=15 mm, bridge=3 mm)
        drawing shingles {
            course = Line((-roof_w / 2 + 8, -roof_l / 2), (-roof_w / 2 + 8, roof_l / 2))
            left_courses = LinearPattern(course, 6, (7, 0))
            course_r = Line((roof_w / 2 - 8, -roof_l / 2), (roof_w / 2 - 8, roof_l / 2))
            right_courses = LinearPattern(course_r, 6, (-7, 0))
        }
    }

    RightOf(back, front, gap=8)
    RightOf(left, back, gap=8)
    RightOf(right, left, gap=8)
    Below(roof, front, gap=8)
    AlignLeft(roof, front)
    AlignBottom(back, front)
    AlignBottom(left, front)
    AlignBottom(right, front)

    assert front.wall.outline.width == 80 mm and left.wall.outline.width == 60 mm, "footprint 80 x 60"
    assert front.wall.outline.height == 70 mm, "walls 70 mm to the eaves"
    assert front.gable.bb.top - front.wall.outline.bb.bottom == 100 mm, "ridge 100 mm up"
    assert front.doorway.leaf.width == 16 mm and front.doorway.arch.bb.top - front.wall.outline.bb.bottom == 28 mm, "door 16 x 28"
    assert front.round_window.c.diameter == 10 mm, "round gable window 10 mm"
    assert roof.panel.height == 60 mm + 2 * 5 mm, "roof overhangs 5 mm at each gable"
    assert roof.bend.width == 16 mm, "hinge band 16 mm"
}
