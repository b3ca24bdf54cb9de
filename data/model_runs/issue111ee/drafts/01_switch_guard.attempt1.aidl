# Request (home): a guard that holds a light switch ON (the freezer's / the fan's switch) so it
# cannot be knocked off by accident. 3 mm clear acrylic, glued.
# - Back plate 90 x 90 mm, corners R6, fits over a UK single switch plate (86 x 86): two holes
#   for the switch's own M3.5 screws, 60.3 mm apart, on the horizontal centre line; a 30 x 30 mm
#   window in the middle for the rocker.
# - A hood over the window, 22 mm deep (clear space from the back plate to the front): two side
#   walls 40 mm tall whose inner faces are 40 mm apart, a top wall between them, and a front
#   52 x 43 mm that overhangs the walls by 3 mm left, right and top. Open at the bottom so an
#   adult reaches up under it to the rocker.
# - Every wall stands in the back plate on two 10 mm tabs and holds the front on two 10 mm
#   tabs (mortises, glued).
# - "LIGHTS ON" engraved filled on the front, bold sans, 6 mm letters, and "reach under"
#   3 mm under it.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

param depth = 22 mm, min = 15 mm, max = 40 mm    # clear space behind the front
param inner = 40 mm, min = 34 mm, max = 52 mm    # between the side walls' inner faces
param tall = 40 mm, min = 34 mm, max = 60 mm     # side walls' height

t = 3 mm
side_x = inner / 2 + t / 2         # centre line of each side wall
top_y = tall / 2 - t / 2           # centre line of the top wall

assembly switch_guard {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=90, height=90, corner_radius=6)
        hole window { w = Rectangle(center=(0, 0), width=30, height=30) }
        screw_l = clearance_hole(size=3.5, cx=-60.3 / 2, cy=0)
        screw_r = clearance_hole(size=3.5, cx=60.3 / 2, cy=0)
        left_mortise = tab_and_slot(part="slot", length=tall, thickness=t, tabs=2, tab=10,
                                    screw=0, rotation=90 deg, cx=-side_x, cy=0)
        right_mortise = tab_and_slot(part="slot", length=tall, thickness=t, tabs=2, tab=10,
                                     screw=0, rotation=90 deg, cx=side_x, cy=0)
        top_mortise = tab_and_slot(part="slot", length=inner, thickness=t, tabs=2, tab=10,
                                   screw=0, rotation=0 deg, cx=0, cy=top_y)
    }

    # a side wall on the sheet: x runs from the back plate (x = 0) to the front (x = depth),
    # the tabs stand t beyond each; y is the wall's height
    def side_wall() -> solid {
        body = Rectangle(bottom_left=(-t, -tall / 2), width=depth + 2 * t, height=tall)
        back_tabs = tab_and_slot(part="tab", length=tall, thickness=t, tabs=2, tab=10, screw=0,
                                 rotation=90 deg, cx=-t, cy=0)
        front_tabs = tab_and_slot(part="tab", length=tall, thickness=t, tabs=2, tab=10, screw=0,
                                  rotation=-90 deg, cx=depth + t, cy=0)
    }
    left = side_wall()
    right = side_wall()

    # the top wall on the sheet: x across the hood, y from the back plate (0) to the front (depth)
    solid top {
        body = Rectangle(bottom_left=(-inner / 2, -t), width=inner, height=depth + 2 * t)
        back_tabs = tab_and_slot(part="tab", length=inner, thickness=t, tabs=2, tab=10, screw=0,
                                 rotation=180 deg, cx=0, cy=-t)
        front_tabs = tab_and_slot(part="tab", length=inner, thickness=t, tabs=2, tab=10, screw=0,
                                  rotation=0 deg, cx=0, cy=depth + t)
    }

    solid front {
        body = Rectangle(bottom_left=(-(inner / 2 + t + 3), -tall / 2), width=inner + 2 * t + 6,
                         height=tall + 3)
        left_mortise = tab_and_slot(part="slot", length=tall, thickness=t, tabs=2, tab=10,
                                    screw=0, rotation=90 deg, cx=-side_x, cy=0)
        right_mortise = tab_and_slot(part="slot", length=tall, thickness=t, tabs=2, tab=10,
                                     screw=0, rotation=90 deg, cx=side_x, cy=0)
        top_mortise = tab_and_slot(part="slot", length=inner, thickness=t, tabs=2, tab=10,
                                   screw=0, rotation=0 deg, cx=0, cy=top_y)
        drawing label {
            word = Text("LIGHTS ON", position=(0, 2), size=6, font="sans:Bold", fill=true)
            hint = Text("reach under", position=(0, -6), size=3)
        }
    }

    # flat on the sheet: plate, then the walls, the top and the front in a row to its right
    RightOf(left, plate, gap=5)
    AlignTop(left, plate)
    RightOf(right, left, gap=5)
    AlignTop(right, plate)
    RightOf(top, right, gap=5)
    AlignTop(top, plate)
    Below(front, top, gap=5)
    AlignLeft(front, left)

    # assembled: the plate lies flat (z 0..3), the hood rises in +z; world y is "up the wall"
    Place(plate, position=(0, 0, 0))
    Place(left, position=(-inner / 2, 0, t), face="left", up="back")
    Place(right, position=(inner / 2 + t, 0, t), face="left", up="back")
    Place(top, position=(0, top_y + t / 2, t), face="front", up="up")
    Place(front, position=(0, 0, t + depth), face="up", up="back")

    # the request's numbers
    assert plate.body.bb.width == 90 mm, "plate 90 wide"
    assert plate.body.bb.height == 90 mm, "plate 90 tall"
    assert plate.screw_r.c.center.x - plate.screw_l.c.center.x == 60.3 mm, "switch screws 60.3 apart"
    assert plate.window.bb.width == 30 mm and plate.window.bb.height == 30 mm, "30 x 30 window"
    assert left.body.bb.width - 2 * t == 22 mm, "hood 22 deep"
    assert left.body.bb.height == 40 mm, "side walls 40 tall"
    assert front.body.bb.width == 52 mm and front.body.bb.height == 43 mm, "front 52 x 43"
    assert plate.screw_r.c.center.x - (side_x + t / 2) >= 5 mm, "screw heads clear the hood"
}
