# AIDL standard library: stands and holders of flat laser-cut parts.
#   import "std/stands.aidl"
# Each is an assembly: its parts laid out flat on the sheet around (cx, cy),
# `gap` apart, and placed in 3D with `Place` (`aidl render --assembled`
# shows the product standing on z = 0; the fit check W0517/W0518 runs).
# The joints are std/joints.aidl's; sizes are nominal (`kerf 0.15 mm` keeps
# them so when cut).

import "std/joints.aidl"

# A phone or tablet stand: two leaning supports crossed by a foot.
# The supports lean back at `angle`.
# Each support is a profile `height` tall with a ledge 6 mm up and a `lip`
# in front that holds the device (a channel 14 mm deep); its depth follows
# from the angle. The foot, `width` long and 40 mm tall, crosses both
# supports in cross-halving slots (`thickness` + `clearance` wide, 20 mm
# deep each). Members: `support` (a list of 2), `foot`.
# Anchor: (cx, cy) is the middle of the `support`s' bottom edge.
def tablet_stand(width=120 mm, height=120 mm, angle=70 deg, lip=12 mm, thickness=3 mm,
                 clearance=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    assert angle > 30 deg and angle < 85 deg, "the back leans at 30 to 85 degrees"
    assert width >= 60 mm and height >= 60 mm, "the stand is at least 60 mm wide and tall"
    t = thickness
    e = 6 mm   # the ledge the device stands on
    f = 40 mm  # the foot's height
    gap = 5 mm
    depth = (height - e) / tan(angle) + 60 mm  # the supports' footprint
    x5 = depth / 2 - 24 mm                     # the back's front face meets the ledge
    x6 = x5 - (height - e) / tan(angle)
    prof = [(-depth / 2, 0 mm), (depth / 2, 0 mm), (depth / 2, e + lip), (depth / 2 - 10 mm, e + lip),
            (depth / 2 - 10 mm, e), (x5, e), (x6, height), (x6 - 15 mm, height), (-depth / 2, 12 mm)]
    for i in range(2) {
        ox = cx + (2 * i - 1) * (depth + gap) / 2
        solid support {
            body = Polygon([(ox + q[0], cy + q[1]) for q in prof])
            Fixed(body)
            slot = cross_halving(depth=f / 2, thickness=t, clearance=clearance, rotation=180 deg,
                                 cx=ox, cy=cy)
        }
        # stood up across x, its front toward -y, crossing the foot at y = 0
        Place(support, rotation=(90 deg, 0, -90 deg),
              position=((2 * i - 1) * (width / 2 - 15 mm) + t / 2, ox, -cy))
    }
    solid foot {
        body = Rectangle(center=(cx, cy - gap - f / 2), width=width, height=f)
        Fixed(body)
        for i in range(2) {
            slot = cross_halving(depth=f / 2, thickness=t, clearance=clearance,
                                 cx=cx + (2 * i - 1) * (width / 2 - 15 mm), cy=cy - gap)
        }
    }
    Place(foot, rotation=(90 deg, 0, 0), position=(-cx, t / 2, f + gap - cy))
}

# A laptop or book stand: two sloping sides joined by cross bars.
# The sides slope at `angle`.
# The sides are `depth` deep, `height` tall at the front (with a 10 mm lip
# that stops the laptop sliding) and rise at `angle` toward the back; the
# bars, `width` long and `height` tall, cross them in cross-halving slots
# (`thickness` + `clearance` wide, half the bar deep) 30 mm from either
# end. Members: `side` (a list of 2), `bar` (a list of 2).
# Anchor: (cx, cy) is the middle of the `side`s' bottom edge.
def laptop_stand(width=260 mm, depth=220 mm, height=30 mm, angle=15 deg, thickness=3 mm,
                 clearance=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    assert angle >= 0 deg and angle < 45 deg, "the top slopes at 0 to 45 degrees"
    assert height >= 20 mm and depth >= 100 mm and width >= 100 mm, "at least 100 mm wide and deep, 20 mm tall"
    t = thickness
    gap = 5 mm
    back = height + depth * tan(angle)
    prof = [(-depth / 2, 0 mm), (depth / 2, 0 mm), (depth / 2, height + 10 mm),
            (depth / 2 - 6 mm, height + 10 mm), (depth / 2 - 6 mm, height + 6 mm * tan(angle)),
            (-depth / 2, back)]
    for i in range(2) {
        ox = cx + (2 * i - 1) * (depth + gap) / 2
        solid side {
            body = Polygon([(ox + q[0], cy + q[1]) for q in prof])
            Fixed(body)
            for k in range(2) {
                slot = cross_halving(depth=height / 2, thickness=t, clearance=clearance,
                                     rotation=180 deg, cx=ox + (2 * k - 1) * (depth / 2 - 30 mm), cy=cy)
            }
        }
        # its front (the lip) toward -y
        Place(side, rotation=(90 deg, 0, -90 deg),
              position=((2 * i - 1) * (width / 2 - 20 mm) + t / 2, ox, -cy))
    }
    for k in range(2) {
        by = cy - gap - height / 2 - k * (height + gap)
        solid bar {
            body = Rectangle(center=(cx, by), width=width, height=height)
            Fixed(body)
            for i in range(2) {
                slot = cross_halving(depth=height / 2, thickness=t, clearance=clearance,
                                     cx=cx + (2 * i - 1) * (width / 2 - 20 mm), cy=by + height / 2)
            }
        }
        # stood up across the sides, 30 mm from the front and from the back
        Place(bar, rotation=(90 deg, 0, 0),
              position=(-cx, (2 * k - 1) * (depth / 2 - 30 mm) + t / 2, height / 2 - by))
    }
}

# A pen or tool holder: a finger-jointed box with a drilled top plate.
# `rows` x `cols` holes of `hole` diameter, spread evenly over the top
# plate inside its joints. The box is `length` x `depth` x `height`, outside
# (`outside=true`) or inside (`outside=false`), from material `thickness`,
# its panels as `finger_box`'s (`front`, `back`, `left`, `right`; the net
# around `bottom` at (cx, cy), placed in 3D standing on z = 0). Members:
# `bottom`, `top`.
# Anchor: (cx, cy) is the centre of `bottom`.
def tool_holder(length=100 mm, depth=70 mm, height=90 mm, thickness=3 mm, finger=10 mm,
                rows=2, cols=3, hole=16 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    L = length if outside else length + 2 * t
    D = depth if outside else depth + 2 * t
    H = height if outside else height + 2 * t
    gap = 5 mm
    px = (L - 2 * t) / cols
    py = (D - 2 * t) / rows
    assert rows >= 1 and cols >= 1, "at least one row and one column of holes"
    assert thickness > 0 mm, "the thickness is more than 0"
    assert hole > 0 mm and hole + 4 mm <= px and hole + 4 mm <= py, "the holes must be 4 mm apart and clear of the joints"
    bottom = finger_panel(width=L, height=D, thickness=t, finger=finger,
                          bottom="slots", right="fingers", top="slots", left="fingers", cx=cx, cy=cy)
    front = finger_panel(width=L, height=H, thickness=t, finger=finger, cx=cx, cy=cy - (D + H) / 2 - gap)
    back = finger_panel(width=L, height=H, thickness=t, finger=finger, cx=cx, cy=cy + (D + H) / 2 + gap)
    left = finger_panel(width=H, height=D, thickness=t, finger=finger,
                        bottom="slots", right="slots", top="slots", left="slots",
                        cx=cx - (L + H) / 2 - gap, cy=cy)
    right = finger_panel(width=H, height=D, thickness=t, finger=finger,
                         bottom="slots", right="slots", top="slots", left="slots",
                         cx=cx + (L + H) / 2 + gap, cy=cy)
    ty = cy + D + H + 2 * gap
    solid top {
        plate = finger_panel(width=L, height=D, thickness=t, finger=finger,
                             bottom="slots", right="fingers", top="slots", left="fingers", cx=cx, cy=ty)
        for r in range(rows) {
            for c in range(cols) {
                hole grid {
                    h = Circle(center=(cx + (c - (cols - 1) / 2) * px, ty + (r - (rows - 1) / 2) * py),
                               diameter=hole)
                    Fixed(h)
                }
                Fixed(grid)
            }
        }
    }
    bottom.outline.center == (cx, cy)
    front.outline.center == (cx, cy - (D + H) / 2 - gap)
    back.outline.center == (cx, cy + (D + H) / 2 + gap)
    left.outline.center == (cx - (L + H) / 2 - gap, cy)
    right.outline.center == (cx + (L + H) / 2 + gap, cy)
    top.plate.outline.center == (cx, ty)
    # assembled as finger_box: each panel folded up from the net
    Place(bottom, position=(-cx, -cy, 0 mm))
    Place(top, position=(-cx, -ty, H - t))
    Place(front, rotation=(90 deg, 0, 0), position=(-cx, t - D / 2, H / 2 - (cy - (D + H) / 2 - gap)))
    Place(back, rotation=(90 deg, 0, 0), position=(-cx, D / 2, H / 2 - (cy + (D + H) / 2 + gap)))
    Place(left, rotation=(0, 90 deg, 0), position=(-L / 2, -cy, cx - (L + H) / 2 - gap + H / 2))
    Place(right, rotation=(0, -90 deg, 0), position=(L / 2, -cy, H / 2 - (cx + (L + H) / 2 + gap)))
}

# A wall shelf: a board on two cross-halved brackets and a back plate.
# The board is `length` x `depth`; the brackets, `height` tall against the
# back plate (as long and tall), reach `depth` in front of it and rise 30 mm
# above the board as book ends. Each bracket crosses the board in
# cross-halving slots and goes through the back plate with two tabs
# (`tab_and_slot`, no screws); the back plate has two clearance holes for
# M`screw` wall screws. Members: `back`, `shelf`, `bracket` (a list of 2).
# Anchor: (cx, cy) is the centre of `back`.
def wall_shelf(length=300 mm, depth=120 mm, height=150 mm, thickness=3 mm, screw=4,
               clearance=0 mm, cx=0 mm, cy=0 mm) -> assembly {
    assert length >= 150 mm and depth >= 60 mm and height >= 80 mm, "at least 150 mm long, 60 mm deep, 80 mm tall"
    t = thickness
    gap = 5 mm
    zs = height - 30 mm  # the board's underside
    inset = 40 mm        # the brackets from the ends
    X = length / 2 - inset
    tab = 20 mm
    by = cy - height / 2
    sy = by - gap  # the board's back edge on the sheet
    solid back {
        body = Rectangle(center=(cx, cy), width=length, height=height)
        Fixed(body)
        for i in range(2) {
            slots = tab_and_slot(part="slot", length=height, thickness=t, tab=tab, screw=0,
                                 clearance=clearance, rotation=90 deg, cx=cx + (2 * i - 1) * X, cy=cy)
            wall = clearance_hole(size=screw, cx=cx + (2 * i - 1) * X / 2, cy=cy + height / 2 - 15 mm)
            Fixed(wall)
        }
    }
    solid shelf {
        body = Rectangle(center=(cx, sy - depth / 2), width=length, height=depth)
        Fixed(body)
        for i in range(2) {
            slot = cross_halving(depth=depth / 2, thickness=t, clearance=clearance,
                                 cx=cx + (2 * i - 1) * X, cy=sy)
        }
    }
    for i in range(2) {
        bx = cx + length / 2 + gap + i * (depth + t + gap)
        solid bracket {
            body = Polygon([(bx, by), (bx + depth + t, by + zs - 20 mm), (bx + depth + t, by + height),
                            (bx, by + height)])
            Fixed(body)
            tabs = tab_and_slot(part="tab", length=height, thickness=t, tab=tab, screw=0,
                                rotation=90 deg, cx=bx, cy=cy)
            slot = cross_halving(depth=depth / 2, thickness=t, clearance=clearance, rotation=-90 deg,
                                 cx=bx + depth + t, cy=by + zs + t / 2)
        }
        # its tabs through the back plate to the wall (y = 0; the shelf toward -y), across the board
        Place(bracket, rotation=(90 deg, 0, -90 deg), position=((1 - 2 * i) * X + t / 2, bx, -by))
    }
    # the back plate on the wall (y -t .. 0), the board on the brackets, its back edge on the plate
    Place(back, rotation=(90 deg, 0, 180 deg), position=(cx, -t, height / 2 - cy))
    Place(shelf, rotation=(180 deg, 0, 180 deg), position=(cx, -t - sy, zs + t))
}
