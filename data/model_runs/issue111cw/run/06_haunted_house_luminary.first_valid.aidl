# Request (holidays): a Halloween haunted-house luminary for an LED tealight, 3 mm poplar ply.
# An open-top finger-jointed box 140 mm wide, 100 mm deep, 110 mm tall (10 mm fingers) with,
# in the front wall, an arched door 26 mm wide and 43 mm tall (bottom 10 mm up) and four
# four-pane windows (20 x 26 mm, 2 mm glazing bars) centred 38 mm either side of the middle at
# 32 mm and 72 mm up; "BOO" stencil-cut 24 mm high into each side wall, reading upright; a
# crescent moon 30 mm tall cut into the back. A house-front facade glued over the front wall
# gives the silhouette: 140 mm walls, a gable roof with 10 mm eaves (ridge 165 mm up) and a
# chimney 16 mm wide reaching 160 mm up; the facade has the same door and windows, lined up
# with the front wall's, a 20 mm round attic window in the gable, and "BOO!" engraved in filled
# letters 10 mm high above the door.

units mm
thickness 3 mm
import "std/joints.aidl"

box_l = 140 mm
box_d = 100 mm
box_h = 110 mm
win_dx = 38 mm
win_ys = [32 mm, 72 mm]
door_w = 26 mm
door_h = 43 mm
door_y = 10 mm
ridge = 165 mm
eave = 10 mm

def window4() -> hole {
    for i in range(2) {
        for j in range(2) {
            pane = Rectangle(center=((i - 0.5) * 11, (j - 0.5) * 14), width=9, height=12)
        }
    }
}

def door() -> hole {
    r = Rectangle(bottom_left=(-door_w / 2, 0), width=door_w, height=door_h - door_w / 2)
    top = Circle(center=(0, door_h - door_w / 2), radius=door_w / 2)
}

assembly luminary {
    box = finger_box(length=box_l, depth=box_d, height=box_h, thickness=3 mm, finger=10 mm,
                     closed=false)

    # the front wall: door and windows, measured from its bottom edge's middle
    front_door = door()
    front_door.bb.center_x == box.front.bb.center_x
    front_door.bb.bottom == box.front.bb.bottom + door_y
    CutInto(front_door, box.front)
    for i in range(2) {
        for j in range(2) {
            fw = window4()
            fw.bb.center == (box.front.bb.center_x + (2 * i - 1) * win_dx,
                             box.front.bb.bottom + win_ys[j])
            CutInto(fw, box.front)
        }
    }

    # the sides: BOO, upright when assembled (a side's top edge is outward in the net)
    hole boo_left { w = Text("BOO", position=(0, 0), size=24, font="sans:Bold", stencil=true,
                             valign="middle", rotation=90 deg) }
    CenterInside(boo_left, box.left)
    CutInto(boo_left, box.left)
    hole boo_right { w = Text("BOO", position=(0, 0), size=24, font="sans:Bold", stencil=true,
                              valign="middle", rotation=-90 deg) }
    CenterInside(boo_right, box.right)
    CutInto(boo_right, box.right)

    # the back: a crescent moon, two arcs meeting at its horns
    hole moon {
        outer = Arc(start=(0, 15), through=(-15, 0), end=(0, -15))
        inner = Arc(start=(0, -15), through=(-6, 0), end=(0, 15))
    }
    moon.bb.center == (box.back.bb.center_x + 25, box.back.bb.bottom + 70)
    CutInto(moon, box.back)

    solid facade {
        walls = Rectangle(bottom_left=(-box_l / 2, 0), width=box_l, height=box_h)
        roof = Polygon([(-box_l / 2 - eave, box_h - 6), (box_l / 2 + eave, box_h - 6),
                        (0, ridge)])
        chimney = Rectangle(bottom_left=(35, 120), width=16, height=40)
        d = door()
        d.bb.center_x == walls.bb.center_x
        d.bb.bottom == walls.bb.bottom + door_y
        for i in range(2) {
            for j in range(2) {
                w = window4()
                w.bb.center == (walls.bb.center_x + (2 * i - 1) * win_dx, walls.bb.bottom + win_ys[j])
            }
        }
        hole attic { c = Circle(center=(0, 135), diameter=20) }
        drawing sign {
            t = Text("BOO!", position=(0, 75), size=10, font="sans:Bold", fill=true,
                     valign="middle")
        }
    }
    RightOf(facade, box, gap=10)
    AlignBottom(facade, box)
    # glued on the front wall's outer face (y = -box_d / 2), reading from the front
    Place(facade, position=(0, -box_d / 2, 0), face="front", up="up")

    assert box.front.bb.width == 140 mm, "140 mm wide"
    assert box.left.bb.height == 100 mm, "100 mm deep"
    assert box.front.bb.height == 110 mm, "110 mm tall"
    assert front_door.bb.width == 26 mm and front_door.bb.height == 43 mm, "door 26 x 43"
    assert front_door.bb.bottom - box.front.bb.bottom == 10 mm, "door 10 mm up"
    assert fw[0][0].bb.width == 20 mm and fw[0][0].bb.height == 26 mm, "windows 20 x 26"
    assert fw[1][1].bb.center_x - box.front.bb.center_x == 38 mm, "windows 38 mm out"
    assert fw[1][1].bb.center_y - box.front.bb.bottom == 72 mm, "upper windows 72 mm up"
    assert fw[0][0].bb.center_y - box.front.bb.bottom == 32 mm, "lower windows 32 mm up"
    assert facade.w[1][1].bb.center_x - facade.walls.bb.center_x ==
        fw[1][1].bb.center_x - box.front.bb.center_x, "facade windows line up (x)"
    assert facade.w[1][1].bb.center_y - facade.walls.bb.bottom ==
        fw[1][1].bb.center_y - box.front.bb.bottom, "facade windows line up (y)"
    assert moon.bb.height == 30 mm, "moon 30 mm tall"
    assert facade.bb.top - facade.walls.bb.bottom == 165 mm, "ridge 165 mm up"
    assert facade.chimney.bb.top - facade.walls.bb.bottom == 160 mm, "chimney 160 mm up"
    assert facade.roof.bb.width - facade.walls.bb.width == 20 mm, "10 mm eaves"
    assert facade.attic.c.diameter == 20 mm, "20 mm attic window"
}
