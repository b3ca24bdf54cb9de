# Request (music): a classroom rack for a diatonic set of 8 Boomwhacker tubes (40 mm
# across), standing upright, 6 mm ply, four parts.
# - Two sides 100 mm deep x 260 mm tall, top corners R20, an 80 x 25 mm hand hole centred
#   235 mm up; each glued into the base by two 25 mm tenons.
# - A rail 80 mm deep, its underside 200 mm above the base top, with 8 holes of 44 mm on a 52 mm pitch, their centres 30 mm from the
#   rail's back edge; the notes C D E F G A B C engraved filled (12 mm) in front of each hole;
#   it passes through a 40 mm through-mortise in each side (one tenon each end).
# - The base 458 x 100 mm, R10 corners, with a 44 mm circle engraved under each rail hole
#   so the tubes stand straight.
# The space between the sides is 8 x 52 = 416 mm.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
n = 8
tube_d = 40 mm
hole_d = 44 mm
pitch = 52 mm
inside = n * pitch
depth = 100 mm
side_h = 260 mm
rail_d = 80 mm
rail_z = 200 mm                 # the rail's underside above the base top
hole_from_back = 30 mm
notes = ["C", "D", "E", "F", "G", "A", "B", "C"]
def hole_x(i) = -inside / 2 + pitch / 2 + i * pitch

def side() -> solid {
    # drawn with the base top on y = 0; x runs along the rack's depth
    board = RoundedRectangle(bottom_left=(-depth / 2, -t), width=depth, height=side_h + t,
                             corner_radii=[20, 20, 0, 0])
    feet = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=25 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-t)
    mortise = tab_and_slot(part="slot", length=rail_d, thickness=t, tabs=1, tab=40 mm,
                           screw=0, cx=0 mm, cy=rail_z + t / 2)
    hole grip { s = Slot(center=(0, 235), length=80, width=25) }
    Fixed(board)
}

assembly rack {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=inside + 2 * t + 30 mm, height=depth,
                                 corner_radius=10)
        m_left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=25 mm,
                              screw=0, rotation=90 deg, cx=-inside / 2 - t / 2, cy=0 mm)
        m_right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=25 mm,
                               screw=0, rotation=90 deg, cx=inside / 2 + t / 2, cy=0 mm)
        drawing spots {
            for i in range(n) {
                ring = Circle(center=(hole_x(i), rail_d / 2 - hole_from_back), diameter=hole_d)
            }
        }
        Fixed(plate)
    }
    Place(base, position=(0, 0, 0), face="up")

    solid rail {
        bar = Rectangle(center=(0, 0), width=inside + 2 * t, height=rail_d)
        left_end = tab_and_slot(part="tab", length=rail_d, thickness=t, tabs=1, tab=40 mm,
                                screw=0, rotation=90 deg, cx=-inside / 2 - t, cy=0 mm)
        right_end = tab_and_slot(part="tab", length=rail_d, thickness=t, tabs=1, tab=40 mm,
                                 screw=0, rotation=-90 deg, cx=inside / 2 + t, cy=0 mm)
        for i in range(n) {
            hole tube { c = Circle(center=(hole_x(i), rail_d / 2 - hole_from_back), diameter=hole_d) }
        }
        drawing names {
            for i in range(n) {
                note = Text(notes[i], position=(hole_x(i), -rail_d / 2 + 13), size=12,
                            font="sans:Bold", valign="middle", fill=true)
            }
        }
        Fixed(bar)
    }
    Place(rail, position=(0, 0, t + rail_z), face="up")

    left = side()
    right = side()
    Place(right, position=(inside / 2, 0, t), face="right", up="up")
    Place(left, position=(-inside / 2, 0, t), face="left", up="up")

    # flat layout
    Above(rail, base, gap=8)
    AlignLeft(rail, base)
    RightOf(left, base, gap=8)
    AlignBottom(left, base)
    RightOf(right, left, gap=8)
    AlignBottom(right, left)

    assert len(rail.tube) == 8, "eight tubes"
    assert rail.tube[1].c.center.x - rail.tube[0].c.center.x == 52 mm, "52 mm pitch"
    assert rail.tube[0].c.diameter - tube_d == 4 mm, "44 mm holes for 40 mm tubes"
    assert rail.bar.bb.top - rail.tube[0].c.center.y == 30 mm, "holes 30 mm from the back"
    assert right.board.bb.height - t == 260 mm, "sides 260 mm tall"
    assert right.mortise.slot[0].bb.center_y - t / 2 == 200 mm, "rail underside 200 mm up"
    assert distance(rail.names.note[0], rail.tube[0].c) >= 2 mm, "a note clear of its hole"
    assert rail.names.note[0].bb.bottom - rail.bar.bb.bottom >= 2 mm, "notes on the rail"
}
