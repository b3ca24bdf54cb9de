# Round mirror frame, 6 mm plywood, cut as two halves to save sheet: a ring 200 mm outside,
# 150 mm inside (for a 160 mm mirror glued behind), split along its horizontal diameter. The
# halves lock with two flat sliding dovetails, one in each side of the ring, centered 87.5 mm
# left and right of the center: one tail each, 25 mm long (the ring's width), 8 mm deep, 10 deg,
# 0.1 mm clearance, tails on the top half pointing down into sockets in the bottom half.
# "LOOKING GOOD" engraved along the top of the ring, 8 mm tall, baseline on a circle of radius
# 84 mm. Laid out with the bottom half 10 mm below the top half's tails.

import "std/joints.aidl"

units mm
thickness 6 mm

param outer_d = 200 mm, min = 150 mm, max = 400 mm
param inner_d = 150 mm, min = 100 mm, max = 350 mm
param dt_depth = 8 mm, min = 5 mm, max = 12 mm

assembly frame {
    solid top {
        disc = Circle(center=(0, 0), diameter=outer_d)
        hole opening { c = Circle(center=(0, 0), diameter=inner_d) }
        hole lower { r = Rectangle(bottom_left=(-outer_d, -outer_d - dt_depth), width=2 * outer_d, height=outer_d) }
        left_tail = dovetail(part="tail", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                             angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                             cx=-(outer_d + inner_d) / 4, cy=0 mm)
        right_tail = dovetail(part="tail", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                              angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                              cx=(outer_d + inner_d) / 4, cy=0 mm)
        drawing words {
            ring = Circle(center=(0, 0), radius=84, construction=true)
            t = Text("LOOKING GOOD", along=ring, size=8)
        }
        # the opening, the halving cutter and the dovetails' cuts are one opening, as meant
        AllowOverlap(opening, lower, left_tail, right_tail)
    }
    solid bottom {
        disc = Circle(center=(0, 0), diameter=outer_d)
        hole opening { c = Circle(center=(0, 0), diameter=inner_d) }
        hole upper { r = Rectangle(bottom_left=(-outer_d, 0), width=2 * outer_d, height=outer_d) }
        left_socket = dovetail(part="socket", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                               angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                               cx=-(outer_d + inner_d) / 4, cy=0 mm)
        right_socket = dovetail(part="socket", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                                angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                                cx=(outer_d + inner_d) / 4, cy=0 mm)
        AllowOverlap(opening, upper, left_socket, right_socket)
    }
    top.disc.center.y - bottom.disc.center.y == dt_depth + 10 mm
    AlignCenterX(bottom.disc, top.disc)

    assert top.disc.diameter == 200 mm and top.opening.c.diameter == 150 mm, "ring 200 / 150 mm"
    assert abs(top.right_tail.bb.center_x - top.disc.center.x - 87.5 mm) < 0.01 mm, "joint 87.5 mm right of center"
    assert abs(top.words.t.size - 8 mm) < 0.001 mm, "8 mm letters"
    assert abs(top.words.ring.radius - 84 mm) < 0.001 mm, "baseline radius 84 mm"
}
