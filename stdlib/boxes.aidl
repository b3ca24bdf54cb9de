# AIDL standard library: laser-cut boxes with lids, sliding lids and dividers.
#   import "std/boxes.aidl"
# Built from the finger-jointed panels of std/joints.aidl. Every box is laid
# out flat (a net, 5 mm apart) around its bottom at (cx, cy) and placed in 3D
# with `Place`: assembled it stands on z = 0, centered on x = y = 0, and the
# fit check (W0517, W0518) tests every joint and every sliding or lifting fit.
# `outside=true` reads length x width x height as the outer size,
# `outside=false` as the inner (the space a user fills). docs/stdlib.md
# ("Boxes") draws the constructions.

import "std/joints.aidl"

# A finger-jointed box with a lift-off lid. The lid is a top plate resting on
# the walls with a smaller plate, the `lip`, glued under it: the lip fits
# inside the walls with `clearance` all round and keeps the lid in place.
# `length` x `width` x `height` (mm) is the outer size (lid included) when
# `outside=true`, else the space inside; `thickness` is the material,
# `finger` the least finger width. Members: `body` (an open finger_box),
# `lid`, `lip`.
def lid_box(length=120 mm, width=80 mm, height=50 mm, thickness=3 mm, finger=10 mm,
            clearance=0.3 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    gap = 5 mm
    lo = length if outside else length + 2 * t
    wo = width if outside else width + 2 * t
    ho = height if outside else height + 2 * t
    hb = ho - t
    assert hb - t > t, "the box must be taller than three thicknesses"
    assert clearance >= 0 mm and clearance < t, "the clearance is between 0 and the thickness"
    body = finger_box(length=lo, depth=wo, height=hb, thickness=t, finger=finger, closed=false,
                      gap=gap, cx=cx, cy=cy)
    ly = cy + wo + hb + 2 * gap
    lx = cx + lo / 2 + gap + (lo - 2 * t - 2 * clearance) / 2
    solid lid {
        plate = Rectangle(center=(cx, ly), width=lo, height=wo)
    }
    solid lip {
        plate = Rectangle(center=(lx, ly), width=lo - 2 * t - 2 * clearance, height=wo - 2 * t - 2 * clearance)
    }
    body.bottom.outline.center == (cx, cy)
    lid.plate.center == (cx, ly)
    lip.plate.center == (lx, ly)
    # assembled: the lid on the walls, the lip under it inside them
    Place(lid, position=(-cx, -ly, hb))
    Place(lip, position=(-lx, -ly, hb - t))
}

# A finger-jointed box whose lid slides in grooves over a low front.
# Flat-cut sheet has no grooves, so each side wall is lined with two strips:
# a `liner` below the lid (floor to lid) and a `rail` above it, one
# thickness plus `clearance` higher; the lid rides on the liners and on the
# front wall (which stands between the side walls, glued to the bottom) and
# is held down by the rails, `clearance` from the walls and the back.
# `length` x `width` x `height` (mm) is the outer size when `outside=true`,
# else the space under the lid between the liners. Members: `bottom`,
# `front`, `back`, `left`, `right`, `liner`, `rail`, `lid`.
def sliding_lid_box(length=120 mm, width=80 mm, height=50 mm, thickness=3 mm, finger=10 mm,
                    clearance=0.3 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    c = clearance
    gap = 5 mm
    lo = length if outside else length + 4 * t
    wo = width if outside else width + 2 * t
    ho = height if outside else height + 4 * t + c
    z1 = ho - 3 * t - c  # the top of the liners and the front wall: the lid's seat
    hf = z1 - t          # the height of the liners and the front wall
    assert hf > t, "the box must be taller than five thicknesses"
    assert c >= 0 mm and c < t, "the clearance is between 0 and the thickness"
    assert lo > 6 * t and wo > 4 * t, "the box must be longer than six and wider than four thicknesses"
    bottom = finger_panel(width=lo, height=wo, thickness=t, finger=finger, bottom="flat", right="fingers",
                          top="slots", left="fingers", cx=cx, cy=cy)
    back = finger_panel(width=lo, height=ho, thickness=t, finger=finger, top="flat",
                        cx=cx, cy=cy + (wo + ho) / 2 + gap)
    left = finger_panel(width=ho, height=wo, thickness=t, finger=finger, bottom="flat", right="slots",
                        top="slots", left="flat", cx=cx - (lo + ho) / 2 - gap, cy=cy)
    right = finger_panel(width=ho, height=wo, thickness=t, finger=finger, bottom="flat", right="flat",
                         top="slots", left="slots", cx=cx + (lo + ho) / 2 + gap, cy=cy)
    fy = cy - wo / 2 - gap - hf / 2
    solid front {
        plate = Rectangle(center=(cx, fy), width=lo - 2 * t, height=hf)
    }
    # the lid: from the front face to `clearance` short of the back wall
    ll = wo - t - c
    ly = cy + wo / 2 + ho + 2 * gap + ll / 2
    grip = min(30 mm, (lo - 2 * t) / 2)
    solid lid {
        plate = Rectangle(center=(cx, ly), width=lo - 2 * t - 2 * c, height=ll)
        hole pull {
            s = Slot(center=(cx, ly - ll / 2 + 4 * t), length=grip, width=2 * t)
        }
        pull.s.center == (cx, ly - ll / 2 + 4 * t)
    }
    bottom.outline.center == (cx, cy)
    back.outline.center == (cx, cy + (wo + ho) / 2 + gap)
    left.outline.center == (cx - (lo + ho) / 2 - gap, cy)
    right.outline.center == (cx + (lo + ho) / 2 + gap, cy)
    front.plate.center == (cx, fy)
    lid.plate.center == (cx, ly)
    Place(bottom, position=(-cx, -cy, 0 mm))
    Place(back, rotation=(90 deg, 0, 0), position=(-cx, wo / 2, ho / 2 - (cy + (wo + ho) / 2 + gap)))
    Place(left, rotation=(0, 90 deg, 0), position=(-lo / 2, -cy, cx - (lo + ho) / 2 - gap + ho / 2))
    Place(right, rotation=(0, -90 deg, 0), position=(lo / 2, -cy, ho / 2 - (cx + (lo + ho) / 2 + gap)))
    Place(front, rotation=(90 deg, 0, 0), position=(-cx, t - wo / 2, t + hf / 2 - fy))
    Place(lid, position=(-cx, -(t + c) / 2 - ly, z1))
    # the liners (floor to the lid, between the front and the back wall) and the rails
    # (over the lid, from the front face to the back wall), left and right, below the front
    for k in range(2) {
        sx = -1 if k == 0 else 1
        iy = fy - hf - gap - k * (hf + gap)
        ry = fy - hf / 2 - 2 * (hf + gap) - gap - t - k * (2 * t + gap)
        solid liner {
            plate = Rectangle(center=(cx, iy), width=wo - 2 * t, height=hf)
        }
        solid rail {
            plate = Rectangle(center=(cx, ry), width=wo - t, height=2 * t)
        }
        liner.plate.center == (cx, iy)
        rail.plate.center == (cx, ry)
        Place(liner, rotation=(90 deg, 0, 90 deg), position=(sx * (lo / 2 - t) - (t if k == 1 else 0 mm), -cx, t + hf / 2 - iy))
        Place(rail, rotation=(90 deg, 0, 90 deg),
              position=(sx * (lo / 2 - t) - (t if k == 1 else 0 mm), -t / 2 - cx, z1 + t + c + t - ry))
    }
}

# An open finger-jointed tray of `rows` x `cols` equal compartments.
# The dividers stand on the bottom, as high as the walls, `clearance` short of
# them, and cross in halving slots `thickness` + `clearance` wide: the ones
# along the length slotted from the top, the ones across from the bottom.
# `length` x `width` x `height` (mm) is the outer size when `outside=true`,
# else the inside. Members: `body` (an open finger_box), `row_divider`,
# `col_divider`.
def divider_tray(length=120 mm, width=80 mm, height=40 mm, rows=2, cols=3, thickness=3 mm,
                 finger=10 mm, clearance=0.3 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    c = clearance
    gap = 5 mm
    lo = length if outside else length + 2 * t
    wo = width if outside else width + 2 * t
    ho = height if outside else height + t
    li = lo - 2 * t
    wi = wo - 2 * t
    hd = ho - t  # the dividers' height: floor to the walls' top
    assert rows >= 1 and cols >= 1, "a tray has at least one row and one column"
    assert c >= 0 mm and c < t, "the clearance is between 0 and the thickness"
    cw = (li - (cols - 1) * t) / cols  # a compartment's length and width
    rw = (wi - (rows - 1) * t) / rows
    assert cw > t and rw > t and hd > 2 * t, "the compartments must be larger than the thickness"
    body = finger_box(length=lo, depth=wo, height=ho, thickness=t, finger=finger, closed=false,
                      gap=gap, cx=cx, cy=cy)
    body.bottom.outline.center == (cx, cy)
    y0 = cy + wo / 2 + ho + 2 * gap + hd / 2
    # the dividers' centers across the tray
    xs = [-li / 2 + (i + 1) * cw + i * t + t / 2 for i in range(cols - 1)]
    ys = [-wi / 2 + (j + 1) * rw + j * t + t / 2 for j in range(rows - 1)]
    for j in range(rows - 1) {
        ny = y0 + j * (hd + gap)
        solid row_divider {
            plate = Rectangle(center=(cx, ny), width=li - 2 * c, height=hd)
            for x in xs {
                hole halving {
                    s = Rectangle(center=(cx + x, ny + hd / 4 + 0.5 mm), width=t + c, height=hd / 2 + 1 mm)
                }
                halving.s.center == (cx + x, ny + hd / 4 + 0.5 mm)
            }
        }
        row_divider.plate.center == (cx, ny)
        Place(row_divider, rotation=(90 deg, 0, 0), position=(-cx, ys[j] + t / 2, t + hd / 2 - ny))
    }
    for i in range(cols - 1) {
        ny = y0 + (rows - 1 + i) * (hd + gap)
        solid col_divider {
            plate = Rectangle(center=(cx, ny), width=wi - 2 * c, height=hd)
            for y in ys {
                hole halving {
                    s = Rectangle(center=(cx + y, ny - hd / 4 - 0.5 mm), width=t + c, height=hd / 2 + 1 mm)
                }
                halving.s.center == (cx + y, ny - hd / 4 - 0.5 mm)
            }
        }
        col_divider.plate.center == (cx, ny)
        Place(col_divider, rotation=(90 deg, 0, 90 deg), position=(xs[i] - t / 2, -cx, t + hd / 2 - ny))
    }
}
