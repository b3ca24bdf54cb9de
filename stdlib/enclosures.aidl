# AIDL standard library: enclosures for circuit boards, finger-jointed.
#   import "std/enclosures.aidl"
# docs/stdlib.md ("Enclosures") has pictures. The walls are std/joints.aidl
# finger_panels; the parts are laid out flat (a net) and placed in 3D with
# `Place`, so `aidl render --assembled` shows the closed box and the fit
# check (W0517, W0518) runs on it.

import "std/joints.aidl"

# A finger-jointed box for a circuit board: standoff holes, ports, vented lid.
# The board is `width` x `height` (mm, its outline), `clearance` from every
# wall; the box's inside is `depth` deep (floor to lid) from material
# `thickness`, so its outer size is (width + 2 clearance + 2 thickness) x
# (height + 2 clearance + 2 thickness) x (depth + 2 thickness). `holes` are the
# board's mounting holes, [x, y] from the board's bottom-left corner; the
# floor gets a hole of `hole_d` under each (for standoffs `standoff` high).
# `ports` are openings [side, position, width, height]: side "left", "right", "front"
# (the board's bottom edge) or "back", position the opening's centre along
# that edge in board coordinates (y for left/right, x for front/back), its
# bottom edge level with the board's top face (standoff + 1.6 mm above the
# floor). `vent` is "slots", "hex" (a hex grid of round holes) or "none", over
# the board's area in the lid. Each part holds a finger_panel, panel.
# Members: `bottom`, `front`, `back`, `left`, `right`, `lid`, `length`,
# `wide`, `tall` (the outer size along x, y and z).
# Anchor: (cx, cy) is the centre of `bottom`.
def board_enclosure(width=85 mm, height=56 mm, depth=25 mm, thickness=3 mm,
                    clearance=2 mm, holes=[[3.5, 3.5], [61.5, 3.5], [3.5, 52.5], [61.5, 52.5]],
                    hole_d=3.2 mm, standoff=5 mm,
                    ports=[["front", 20, 10, 4], ["right", 28, 14, 8]],
                    vent="slots", finger=10 mm, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    gap = 5 mm
    assert (1 if vent == "slots" or vent == "hex" or vent == "none" else 0) == 1, "vent is \"slots\", \"hex\" or \"none\""
    assert clearance >= 0 mm and depth > standoff + 1.6 mm, "the box must be deeper than the standoffs and the board"
    # the outer size: length along x, wide along y, tall along z
    length = width + 2 * clearance + 2 * t
    wide = height + 2 * clearance + 2 * t
    tall = depth + 2 * t
    # where the panels lie in the net (as finger_box)
    fy = cy - (wide + tall) / 2 - gap
    by = cy + (wide + tall) / 2 + gap
    lx = cx - (length + tall) / 2 - gap
    rx = cx + (length + tall) / 2 + gap
    ly = cy + wide + tall + 2 * gap
    # the board's top face above the inside of the floor: the ports' bottom edge
    deck = standoff + 1.6 mm
    for p in ports {
        assert (1 if p[0] == "left" or p[0] == "right" or p[0] == "front" or p[0] == "back" else 0) == 1, "a port's side is \"left\", \"right\", \"front\" or \"back\""
        assert t + deck + p[3] <= tall - t, "a port reaches above the lid: make it lower or the box deeper"
    }
    solid bottom {
        panel = finger_panel(width=length, height=wide, thickness=t, finger=finger,
                             bottom="slots", right="fingers", top="slots", left="fingers", cx=cx, cy=cy)
        panel.outline.center == (cx, cy)
        for h in holes {
            hole standoff_hole {
                c = Circle(center=(cx - width / 2 + h[0], cy - height / 2 + h[1]), diameter=hole_d)
                Fixed(c.center)
            }
            standoff_hole.c.center == (cx - width / 2 + h[0], cy - height / 2 + h[1])
        }
    }
    solid front {
        panel = finger_panel(width=length, height=tall, thickness=t, finger=finger, cx=cx, cy=fy)
        panel.outline.center == (cx, fy)
        for p in ports {
            if p[0] == "front" {
                hole port {
                    r = Rectangle(center=(cx - width / 2 + p[1], fy - tall / 2 + t + deck + p[3] / 2),
                                  width=p[2], height=p[3])
                    Fixed(r.center)
                }
                port.r.center == (cx - width / 2 + p[1], fy - tall / 2 + t + deck + p[3] / 2)
            }
        }
    }
    solid back {
        panel = finger_panel(width=length, height=tall, thickness=t, finger=finger, cx=cx, cy=by)
        panel.outline.center == (cx, by)
        for p in ports {
            if p[0] == "back" {
                hole port {
                    r = Rectangle(center=(cx - width / 2 + p[1], by - tall / 2 + t + deck + p[3] / 2),
                                  width=p[2], height=p[3])
                    Fixed(r.center)
                }
                port.r.center == (cx - width / 2 + p[1], by - tall / 2 + t + deck + p[3] / 2)
            }
        }
    }
    solid left {
        panel = finger_panel(width=tall, height=wide, thickness=t, finger=finger,
                             bottom="slots", right="slots", top="slots", left="slots", cx=lx, cy=cy)
        panel.outline.center == (lx, cy)
        for p in ports {
            if p[0] == "left" {
                hole port {
                    r = Rectangle(center=(lx + tall / 2 - t - deck - p[3] / 2, cy - height / 2 + p[1]),
                                  width=p[3], height=p[2])
                    Fixed(r.center)
                }
                port.r.center == (lx + tall / 2 - t - deck - p[3] / 2, cy - height / 2 + p[1])
            }
        }
    }
    solid right {
        panel = finger_panel(width=tall, height=wide, thickness=t, finger=finger,
                             bottom="slots", right="slots", top="slots", left="slots", cx=rx, cy=cy)
        panel.outline.center == (rx, cy)
        for p in ports {
            if p[0] == "right" {
                hole port {
                    r = Rectangle(center=(rx - tall / 2 + t + deck + p[3] / 2, cy - height / 2 + p[1]),
                                  width=p[3], height=p[2])
                    Fixed(r.center)
                }
                port.r.center == (rx - tall / 2 + t + deck + p[3] / 2, cy - height / 2 + p[1])
            }
        }
    }
    solid lid {
        panel = finger_panel(width=length, height=wide, thickness=t, finger=finger,
                             bottom="slots", right="fingers", top="slots", left="fingers", cx=cx, cy=ly)
        panel.outline.center == (cx, ly)
        # the vents cover the board's area less 5 mm all round, 6 mm apart
        vw = width - 10 mm
        vh = height - 10 mm
        if vent == "slots" {
            nx = floor(vw / 6 mm)
            for i in range(nx) {
                hole slot {
                    s = Slot(center=(cx + (i - (nx - 1) / 2) * 6 mm, ly), length=vh, width=3 mm, rotation=90 deg)
                    Fixed(s.center)
                }
                slot.s.center == (cx + (i - (nx - 1) / 2) * 6 mm, ly)
            }
        }
        if vent == "hex" {
            # rows 6 sin(60 deg) apart, every second row shifted half a pitch
            rows = floor((vh - 4 mm) / (6 mm * sin(60 deg))) + 1
            cols = floor((vw - 4 mm) / 6 mm) + 1
            for j in range(rows) {
                for i in range(cols - j % 2) {
                    hole cell {
                        c = Circle(center=(cx + (i - (cols - 1 - j % 2) / 2) * 6 mm,
                                           ly + (j - (rows - 1) / 2) * 6 mm * sin(60 deg)), diameter=4 mm)
                        Fixed(c.center)
                    }
                    cell.c.center == (cx + (i - (cols - 1 - j % 2) / 2) * 6 mm, ly + (j - (rows - 1) / 2) * 6 mm * sin(60 deg))
                }
            }
        }
    }
    # assembled: each panel folded up from the net about its edge on the bottom (as finger_box)
    Place(bottom, position=(-cx, -cy, 0 mm))
    Place(front, rotation=(90 deg, 0, 0), position=(-cx, t - wide / 2, tall / 2 - fy))
    Place(back, rotation=(90 deg, 0, 0), position=(-cx, wide / 2, tall / 2 - by))
    Place(left, rotation=(0, 90 deg, 0), position=(-length / 2, -cy, lx + tall / 2))
    Place(right, rotation=(0, -90 deg, 0), position=(length / 2, -cy, tall / 2 - rx))
    Place(lid, position=(-cx, -ly, tall - t))
}
