# Request: a handle for an 8 mm ferro rod (fire steel), four glued plywood layers with one
# outline: 104 mm long from the flat front face (18 mm high, where the rod comes out) to the
# rounded butt, a grip with a finger groove: half-widths 10 mm at 18 mm from the front, 13.5 mm
# at 38, 11 at 58 (the groove), 14 at 78, 11 at 96; never more than 30 mm wide. A 5 mm lanyard
# hole through every layer, centred 8 mm from the butt. From the top: a 3 mm cheek with "SPARK"
# engraved (7 mm bold letters, filled) at 60 mm from the front; two 4 mm core layers, each with an
# 8 mm wide channel 25 mm deep from the front face on the axis for the rod's end; a plain 3 mm
# cheek.

HALF = [(0, 0), (0, 9 mm), (18 mm, 10 mm), (38 mm, 13.5 mm), (58 mm, 11 mm), (78 mm, 14 mm),
        (96 mm, 11 mm), (104 mm, 0)]

thickness 3 mm

def layer(kind="plain") -> solid {
    grip = Spline(mirror(HALF, about="x"), closed=true, corners=[1, 13])
    hole lanyard {
        c = Circle(center=(96 mm, 0), diameter=5 mm)
    }
    if kind == "core" {
        hole channel {
            rod = Rectangle(corner=(-1 mm, -4 mm), opposite=(25 mm, 4 mm))
        }
    }
    if kind == "named" {
        drawing name {
            t = Text("SPARK", position=(60 mm, 0), size=7 mm, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

assembly handle {
    top = layer(kind="named")
    solid core_a {
        thickness 4 mm
        l = layer(kind="core")
    }
    solid core_b {
        thickness 4 mm
        l = layer(kind="core")
    }
    bottom = layer(kind="plain")

    # flat on the sheet: a column
    Below(core_a, top, gap=6 mm)
    AlignLeft(core_a, top)
    Below(core_b, core_a, gap=6 mm)
    AlignLeft(core_b, core_a)
    Below(bottom, core_b, gap=6 mm)
    AlignLeft(bottom, core_b)

    # in 3D: stacked, the named cheek on top
    Place(bottom, position=(0, 0, 0))
    Place(core_a, position=(0, 0, 3 mm))
    Place(core_b, position=(0, 0, 7 mm))
    Place(top, position=(0, 0, 11 mm))

    assert top.grip.points[7].x - top.grip.points[0].x == 104 mm, "104 mm long"
    assert top.grip.points[1].y - top.grip.points[13].y == 18 mm, "18 mm front face"
    assert top.grip.points[4].y == 11 mm and top.grip.points[3].y == 13.5 mm and
        top.grip.points[5].y == 14 mm, "groove between the two swells"
    assert top.grip.bb.height <= 30 mm, "never more than 30 mm wide"
    assert top.lanyard.c.diameter == 5 mm, "5 mm lanyard hole"
    assert top.grip.points[7].x - top.lanyard.c.center.x == 8 mm, "8 mm from the butt"
    assert core_a.l.channel.rod.bb.height == 8 mm and core_b.l.channel.rod.bb.height == 8 mm,
        "8 mm channel"
    assert core_a.l.channel.rod.bb.right - core_a.l.grip.points[0].x == 25 mm, "25 mm deep"
    assert core_a.l.channel.rod.bb.center_y == core_a.l.grip.points[0].y, "on the axis"
    assert top.name.t.position.x - top.grip.points[0].x == 60 mm, "name 60 from the front"
    assert distance(top.name, top.lanyard) >= 3 mm, "name clear of the lanyard hole"
    assert top.name.bb.height <= 2 * 10 mm, "name within the grip"
}
