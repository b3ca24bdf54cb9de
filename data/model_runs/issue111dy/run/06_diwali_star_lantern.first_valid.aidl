# Request (holidays): a hanging Diwali star lantern (akash kandil) for an LED tealight,
# in 3 mm ply. Two five-pointed star faces, tips 120 mm and notches 55 mm from the centre,
# one tip up, tips rounded R2, 60 mm apart (inside). Each face has DIWALI cut through as a
# bold stencil, 14 mm capitals, across its centre, a 36 x 10 slot window along each tip
# centred 80 mm out, and a 4 mm cord hole in the top tip 108 mm up. The faces are held by
# two spacers 20 wide at the two upper notches (radial, centred 40 mm out), each with a
# 10 mm tenon into a mortise in each face, and a floor 60 wide for the tealight, 30 mm
# below the centre, with two 15 mm tenons into each face. Five parts.

import "std/joints.aidl"

thickness 3 mm

outer = 120 mm
inner = 55 mm
depth = 60 mm       # between the faces
spacer_r = 40 mm
floor_y = -30 mm
hang_z = 150 mm     # the star's centre in 3D

def star_face() -> solid {
    star = Star(center=(0, 0), points=5, outer_radius=outer, inner_radius=inner,
                tip_radius=2)
    hole words {
        t = Text("DIWALI", position=(0, 0), size=14, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    hole windows {
        for i in range(5) {
            w = Slot(center=polar((0, 0), 80, 90 deg + i * 72 deg), length=36, width=10,
                     rotation=90 deg + i * 72 deg)
        }
    }
    hole cord {
        c = Circle(center=(0, 108), diameter=4)
    }
    left_mortise = tab_and_slot(part="slot", length=20 mm, thickness=3 mm, tabs=1,
                                tab=10 mm, screw=0, rotation=126 deg,
                                cx=spacer_r * cos(126 deg), cy=spacer_r * sin(126 deg))
    right_mortise = tab_and_slot(part="slot", length=20 mm, thickness=3 mm, tabs=1,
                                 tab=10 mm, screw=0, rotation=54 deg,
                                 cx=spacer_r * cos(54 deg), cy=spacer_r * sin(54 deg))
    floor_mortise = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, tabs=2,
                                 tab=15 mm, screw=0, rotation=0 deg, cx=0 mm, cy=floor_y)
}

# a spacer: x across its 20 mm width, y between the faces, its tenons' tips 3 mm past each
def spacer() -> solid {
    body = Rectangle(center=(0, 0), width=20, height=depth + 6 mm)
    a = tab_and_slot(part="tab", length=20 mm, thickness=3 mm, tabs=1, tab=10 mm, screw=0,
                     rotation=0 deg, cx=0 mm, cy=depth / 2 + 3 mm)
    b = tab_and_slot(part="tab", length=20 mm, thickness=3 mm, tabs=1, tab=10 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=-depth / 2 - 3 mm)
}

assembly lantern {
    front = star_face()
    back = star_face()
    left_spacer = spacer()
    right_spacer = spacer()
    solid floor {
        body = Rectangle(center=(0, 0), width=60, height=depth + 6 mm)
        a = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=15 mm,
                         screw=0, rotation=0 deg, cx=0 mm, cy=depth / 2 + 3 mm)
        b = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=15 mm,
                         screw=0, rotation=180 deg, cx=0 mm, cy=-depth / 2 - 3 mm)
    }

    # flat on the sheet
    RightOf(back, front, gap=10)
    AlignTop(back, front)
    RightOf(left_spacer, back, gap=10)
    AlignTop(left_spacer, back)
    RightOf(right_spacer, left_spacer, gap=10)
    AlignTop(right_spacer, left_spacer)
    RightOf(floor, right_spacer, gap=10)
    AlignTop(floor, right_spacer)

    # in 3D: faces upright, front toward -y; spacers radial; floor flat
    Place(front, position=(0, -depth / 2, hang_z), face="front", up="up")
    Place(back, position=(0, depth / 2, hang_z), face="back", up="up")
    Place(left_spacer,
          position=(spacer_r * cos(126 deg) + 1.5 mm * sin(126 deg), 0,
                    hang_z + spacer_r * sin(126 deg) - 1.5 mm * cos(126 deg)),
          face=(-sin(126 deg), 0, cos(126 deg)), up="back")
    Place(right_spacer,
          position=(spacer_r * cos(54 deg) + 1.5 mm * sin(54 deg), 0,
                    hang_z + spacer_r * sin(54 deg) - 1.5 mm * cos(54 deg)),
          face=(-sin(54 deg), 0, cos(54 deg)), up="back")
    Place(floor, position=(0, 0, hang_z + floor_y - 1.5 mm), face="up", up="back")

    assert front.star.outer_radius == 120 mm and front.star.inner_radius == 55 mm,
        "tips 120, notches 55"
    assert left_spacer.body.bb.height - 2 * 3 mm == 60 mm, "faces 60 apart"
    assert floor.body.bb.width == 60 mm, "floor 60 wide"
    assert len(front.windows.w) == 5, "a window in each tip"
    assert distance(front.windows.w[0].center, front.star.center) == 80 mm, "windows 80 out"
    assert front.cord.c.center.y - front.star.center.y == 108 mm, "cord hole 108 up"
    assert distance(front.right_mortise.slot[0].bb.center, front.star.center) == 40 mm,
        "spacers 40 out"
    assert front.star.center.y - front.floor_mortise.bb.center_y == 30 mm,
        "floor 30 below the centre"
    assert distance(front.words, front.windows) >= 3 mm, "lettering clear of the windows"
}
