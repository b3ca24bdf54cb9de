# Request: a village sign for Little Wallop's green, 6 mm exterior ply, 480 mm wide and
# 410 mm tall: too tall for my 600 x 400 bed, so it is two panels locked by a flat sliding
# dovetail (3 tails, 12 mm deep, 0.15 mm clearance) along the line 110 mm above the bottom.
# - Lower panel, 480 x 110 (its tails reach 12 mm into the upper panel): "LITTLE WALLOP" in
#   bold sans engraved filled, 50 mm tall at most and no wider than 360 mm, centred.
# - Upper panel, 300 tall, its top an arch rising from 260 mm at the sides to 300 mm in the
#   middle: the scene cut through as openings standing on a ground line 40 mm above the joint:
#   a church (nave 110 x 55 with a 35 mm pitched roof, tower 34 x 110 with a 70 mm spire),
#   a tree (80 mm canopy on a 14 x 70 trunk) and a 40 mm sun; "DOMESDAY 1086" engraved 8 mm
#   tall, centred, baseline 18 mm above the joint.
# - Two 40 x 320 mm battens behind, centred 210 mm either side of the middle, from 20 mm above
#   the bottom; each panel is screwed to them with M4 countersunk screws (4 per panel, 9 mm
#   heads; 3.3 mm pilots in the battens), and two M8 carriage bolts per side go through the
#   upper panel and batten into the posts (8.5 mm holes).
# Scene and lettering stay at least 10 mm clear of every hole and the joint.

import "std/joints.aidl"
import "std/fasteners.aidl"

t = 6 mm
thickness t
half_w = 240 mm
joint_y = 110 mm
ground_y = joint_y + 40 mm
batten_x = 210 mm
screw_y_low = [30 mm, 85 mm]
screw_y_up = [150 mm, 320 mm]
bolt_y = [200 mm, 280 mm]

def batten(s=1) -> solid {
    body = Rectangle(bottom_left=(s * batten_x - 20 mm, 20 mm), width=40 mm, height=320 mm)
    for y in screw_y_low + screw_y_up {
        hole pilot { c = Circle(center=(s * batten_x, y), diameter=3.3 mm) }
    }
    for y in bolt_y {
        hole bolt { c = Circle(center=(s * batten_x, y), diameter=8.5 mm) }
    }
}

assembly sign {
    solid lower {
        body = Rectangle(bottom_left=(-half_w, 0), width=2 * half_w, height=joint_y + 12 mm)
        tails = dovetail(part="tail", length=2 * half_w, depth=12 mm, tails=3, cx=0, cy=joint_y)
        for x in [-batten_x, batten_x] {
            for y in screw_y_low {
                screw = clearance_hole(size=4, cx=x, cy=y)
            }
        }
        Countersink(screw, diameter=9 mm)
        drawing name {
            word = Text("LITTLE WALLOP", position=(0, 55 mm), size=50, font="sans:Bold",
                        valign="middle", fill=true, max_width=360 mm)
        }
    }

    solid upper {
        bottom = Line((-half_w, joint_y), (half_w, joint_y))
        right = Line((half_w, joint_y), (half_w, joint_y + 260 mm))
        top = Arc(start=(half_w, joint_y + 260 mm), through=(0, joint_y + 300 mm),
                  end=(-half_w, joint_y + 260 mm))
        left = Line((-half_w, joint_y + 260 mm), (-half_w, joint_y))
        sockets = dovetail(part="socket", length=2 * half_w, depth=12 mm, tails=3,
                           clearance=0.15 mm, cx=0, cy=joint_y)
        for x in [-batten_x, batten_x] {
            for y in screw_y_up {
                screw = clearance_hole(size=4, cx=x, cy=y)
            }
            for y in bolt_y {
                hole bolt { c = Circle(center=(x, y), diameter=8.5 mm) }
            }
        }
        Countersink(screw, diameter=9 mm)
        hole scene {
            nave = Rectangle(bottom_left=(-150 mm, ground_y), width=110 mm, height=55 mm)
            roof = Triangle(center=(-95 mm, ground_y + 55 mm + 17.5 mm), base=110 mm, height=35 mm)
            tower = Rectangle(bottom_left=(-40 mm, ground_y), width=34 mm, height=110 mm)
            spire = Triangle(center=(-23 mm, ground_y + 110 mm + 35 mm), base=34 mm, height=70 mm)
            canopy = Circle(center=(110 mm, ground_y + 100 mm), diameter=80 mm)
            trunk = Rectangle(bottom_left=(103 mm, ground_y), width=14 mm, height=70 mm)
            sun = Circle(center=(40 mm, ground_y + 180 mm), diameter=40 mm)
        }
        drawing date {
            d = Text("DOMESDAY 1086", position=(0, joint_y + 18 mm), size=8)
        }
    }

    left_batten = batten(s=-1)
    right_batten = batten(s=1)

    # flat: the upper panel above the lower, battens to the right
    Above(upper, lower, gap=8)
    AlignCenterX(upper, lower)
    RightOf(left_batten, upper, gap=8)
    AlignBottom(left_batten, lower)
    RightOf(right_batten, left_batten, gap=8)
    AlignBottom(right_batten, left_batten)

    # assembled: facing the road, battens behind, bottom 500 mm up the posts
    Place(lower, position=(0, 0, 500 mm), face="front", up="up")
    Place(upper, position=(0, 0, 500 mm), face="front", up="up")
    Place(left_batten, position=(0, t, 500 mm), face="front", up="up")
    Place(right_batten, position=(0, t, 500 mm), face="front", up="up")

    assert lower.body.width == 480 mm and upper.bottom.length == 480 mm, "480 wide"
    assert lower.body.height - 12 mm == 110 mm, "lower panel 110 below the joint"
    assert upper.top.through.y - upper.bottom.start.y == 300 mm, "upper panel 300 tall"
    assert upper.right.length == 260 mm, "arch springs at 260"
    assert upper.bb.height <= 400 mm and upper.bb.width <= 600 mm, "upper panel fits the bed"
    assert lower.bb.height <= 400 mm and lower.bb.width <= 600 mm, "lower panel fits the bed"
    assert len(lower.tails.cut) >= 3 and len(upper.sockets.cut) == 3, "three tails"
    assert lower.name.word.size <= 50 mm and lower.name.word.bb.width <= 360 mm, "name at most 50 tall, 360 wide"
    assert abs(lower.name.word.bb.center_x - lower.body.bb.center_x) < 1 mm, "name centred"
    assert len(lower.screw) == 4 and len(upper.screw) == 4, "4 screws per panel"
    assert len(upper.bolt) == 4, "two carriage bolts a side"
    assert lower.screw[0].c.diameter == 4.5 mm and upper.bolt[0].c.diameter == 8.5 mm, "M4 and M8 holes"
    assert upper.scene.nave.width == 110 mm and upper.scene.nave.height == 55 mm, "nave 110 x 55"
    assert upper.scene.roof.height == 35 mm and upper.scene.spire.height == 70 mm, "roof 35, spire 70"
    assert upper.scene.tower.width == 34 mm and upper.scene.tower.height == 110 mm, "tower 34 x 110"
    assert upper.scene.canopy.diameter == 80 mm and upper.scene.sun.diameter == 40 mm, "tree and sun"
    assert upper.scene.nave.bb.bottom - upper.bottom.start.y == 40 mm, "ground 40 above the joint"
    assert upper.date.d.size == 8 mm, "8 mm date"
    assert upper.date.d.position.y - upper.bottom.start.y == 18 mm, "date 18 above the joint"
    assert distance(upper.scene, upper.sockets) >= 10 mm, "scene clear of the joint"
    assert distance(upper.scene, upper.bolt) >= 10 mm and distance(upper.scene, upper.screw) >= 10 mm, "scene clear of the holes"
    assert distance(upper.scene, upper.top) >= 10 mm, "scene clear of the arch"
    assert distance(upper.date, upper.sockets) >= 3 mm and distance(upper.date, upper.scene) >= 10 mm, "date clear"
    assert distance(lower.name, lower.screw) >= 10 mm and distance(lower.name, lower.tails) >= 10 mm, "name clear"
    assert left_batten.body.width == 40 mm and left_batten.body.height == 320 mm, "40 x 320 battens"
    assert len(left_batten.pilot) == 4 and len(left_batten.bolt) == 2, "batten holes"
}
