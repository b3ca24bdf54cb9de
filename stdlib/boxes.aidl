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
# `outside=true`, else the space inside (floor to the lip); `thickness` is the material,
# `finger` the least finger width. Members: `body` (an open finger_box),
# `lid`, `lip`. An opening through the lid (a coin slot: `CutInto(slot, box.lid)`)
# must be cut into the `lip` too (`CutInto(slot2, box.lip)`, the same shape where
# the lip lies on the sheet), or the lip glued under it closes it. The walls
# face as finger_box's: their top faces (an engraving as drawn) and the lid's
# look out; a side's +y in the net is the box's front.
# Anchor: (cx, cy) is the centre of `body.bottom`.
def lid_box(length=120 mm, width=80 mm, height=50 mm, thickness=3 mm, finger=10 mm,
            clearance=0.3 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    gap = 5 mm
    lo = length if outside else length + 2 * t
    wo = width if outside else width + 2 * t
    ho = height if outside else height + 3 * t  # inside: floor to the lip under the lid
    hb = ho - t
    # over the arguments, so a form's ranges follow them (hb > 2 t; c < t)
    assert height > (3 if outside else 1) * thickness, "the box must be taller than three thicknesses (one, inside)"
    assert clearance >= 0 mm and clearance < thickness, "the clearance is between 0 and the thickness"
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
# `front`, `back`, `left`, `right`, `liner`, `rail`, `lid`. The lid has a finger
# pull of its own, `lid.pull`: a slot across its middle (up to 30 mm long, 2 x
# `thickness` wide) 4 x `thickness` from its front edge, the edge at the bottom of
# the lid on the flat sheet, where the lid lies with `length` along x; a hole or a
# drawing added to the lid keeps clear of it. Only the front's and the lid's top
# faces (an engraving as drawn) look out: the back's, the sides' and the bottom's
# look in, so a label meant to be read outside goes on `front` or `lid`; a side's
# +y in the net is the box's back.
# Anchor: (cx, cy) is the centre of `bottom`.
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
    assert clearance >= 0 mm and clearance < thickness, "the clearance is between 0 and the thickness"
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
    # the pull: 2 t wide, 4 t from the front edge, on a short lid (a thick sheet) at most a
    # third of the lid wide and in its middle, so a third of the lid stays either side
    pw = min(2 * t, ll / 3)
    py = ly - ll / 2 + min(4 * t, ll / 2)
    solid lid {
        plate = Rectangle(center=(cx, ly), width=lo - 2 * t - 2 * c, height=ll)
        hole pull {
            s = Slot(center=(cx, py), length=grip, width=pw)
        }
        pull.s.center == (cx, py)
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
# With `rows=1` (or `cols=1`) the dividers cross nothing: each then stands on
# two tabs `thickness` deep in slots of the bottom (`thickness` + `clearance`
# wide), a quarter of its length in from each end, so it keeps its place.
# `length` x `width` x `height` (mm) is the outer size when `outside=true`,
# else the inside. Members: `body` (an open finger_box, its panels laid out as
# finger_box's: the front and back upright, the sides' top edges outward),
# `row_divider`, `col_divider`. Assembled, the bottom's underside lies on z = 0,
# centred on x = y = 0, and the walls' tops at z = the outer height.
# `divider_height` (0: as high as the walls) is the dividers' height above the
# bottom: lower them to leave room for a lid's locating plate or a finger's reach.
# Anchor: (cx, cy) is the centre of `body.bottom`.
def divider_tray(length=120 mm, width=80 mm, height=40 mm, rows=2, cols=3, thickness=3 mm,
                 finger=10 mm, clearance=0.3 mm, outside=true, divider_height=0 mm, cx=0 mm,
                 cy=0 mm) -> assembly {
    t = thickness
    c = clearance
    gap = 5 mm
    lo = length if outside else length + 2 * t
    wo = width if outside else width + 2 * t
    ho = height if outside else height + t
    li = lo - 2 * t
    wi = wo - 2 * t
    hd = divider_height if divider_height > 0 mm else ho - t  # floor to the walls' top
    assert divider_height <= ho - t, "the dividers are at most as high as the walls (less the bottom)"
    assert rows >= 1 and cols >= 1, "a tray has at least one row and one column"
    assert clearance >= 0 mm and clearance < thickness, "the clearance is between 0 and the thickness"
    cw = (li - (cols - 1) * t) / cols  # a compartment's length and width
    rw = (wi - (rows - 1) * t) / rows
    # cw > t, rw > t and hd > 2 t, written over the arguments (a form's ranges follow them)
    assert length > (2 * cols + (1 if outside else -1)) * thickness, "the compartments must be longer than the thickness"
    assert width > (2 * rows + (1 if outside else -1)) * thickness, "the compartments must be wider than the thickness"
    assert height > (3 if outside else 2) * thickness, "the dividers (the walls less the bottom) must be taller than twice the thickness"
    assert divider_height == 0 mm or divider_height > 2 * thickness, "the dividers must be taller than twice the thickness"
    body = finger_box(length=lo, depth=wo, height=ho, thickness=t, finger=finger, closed=false,
                      gap=gap, cx=cx, cy=cy)
    body.bottom.outline.center == (cx, cy)
    y0 = cy + wo / 2 + ho + 2 * gap + hd / 2
    # the dividers' centers across the tray
    xs = [-li / 2 + (i + 1) * cw + i * t + t / 2 for i in range(cols - 1)]
    ys = [-wi / 2 + (j + 1) * rw + j * t + t / 2 for j in range(rows - 1)]
    tw = min(15 mm, li / 6)  # the tabs of a divider that crosses nothing
    tw_c = min(15 mm, wi / 6)
    for j in range(rows - 1) {
        ny = y0 + j * (hd + gap)
        solid row_divider {
            plate = Rectangle(center=(cx, ny), width=li - 2 * c, height=hd)
            if cols == 1 {  # crossing nothing: two tabs in slots of the bottom
                for u in [-li / 4, li / 4] {
                    tab = Rectangle(center=(cx + u, ny - hd / 2 - t / 2), width=tw, height=t)
                    Fixed(tab)
                }
            }
            for x in xs {
                hole halving {
                    s = Rectangle(center=(cx + x, ny + hd / 4 + 0.5 mm), width=t + c, height=hd / 2 + 1 mm)
                }
                halving.s.center == (cx + x, ny + hd / 4 + 0.5 mm)
            }
        }
        row_divider.plate.center == (cx, ny)
        Place(row_divider, rotation=(90 deg, 0, 0), position=(-cx, ys[j] + t / 2, t + hd / 2 - ny))
        if cols == 1 {  # crossing nothing: its two tabs' slots in the bottom
            for u in [-li / 4, li / 4] {
                hole row_slot {
                    s = Rectangle(center=(cx + u, cy + ys[j]), width=tw + c, height=t + c)
                }
                row_slot.s.center == (cx + u, cy + ys[j])
                CutInto(row_slot, body.bottom)
            }
        }
    }
    for i in range(cols - 1) {
        ny = y0 + (rows - 1 + i) * (hd + gap)
        solid col_divider {
            plate = Rectangle(center=(cx, ny), width=wi - 2 * c, height=hd)
            if rows == 1 {
                for u in [-wi / 4, wi / 4] {
                    tab = Rectangle(center=(cx + u, ny - hd / 2 - t / 2), width=tw_c, height=t)
                    Fixed(tab)
                }
            }
            for y in ys {
                hole halving {
                    s = Rectangle(center=(cx + y, ny - hd / 4 - 0.5 mm), width=t + c, height=hd / 2 + 1 mm)
                }
                halving.s.center == (cx + y, ny - hd / 4 - 0.5 mm)
            }
        }
        col_divider.plate.center == (cx, ny)
        Place(col_divider, rotation=(90 deg, 0, 90 deg), position=(xs[i] - t / 2, -cx, t + hd / 2 - ny))
        if rows == 1 {
            for u in [-wi / 4, wi / 4] {
                hole col_slot {
                    s = Rectangle(center=(cx + xs[i], cy + u), width=t + c, height=tw_c + c)
                }
                col_slot.s.center == (cx + xs[i], cy + u)
                CutInto(col_slot, body.bottom)
            }
        }
    }
}

# A finger-jointed box whose lid turns on pins cut from the sheet.
# Two cheeks glued under the lid's back corners hang outside the side walls;
# a pin, a strip `pin` wide (0: the thickness) and as long as a wall and a
# cheek, sits tight in a hole through each side wall near its back top corner
# and turns in a round hole in the cheek (the pin's diagonal plus
# `clearance`). The lid overhangs the side walls by the cheeks. Opening, the
# lid's back edge swings down behind the pivot: the back wall and the side
# walls behind the pivot are lowered by that swing plus `clearance`.
# `length` x `width` x `height` (mm) is the outer size (the lid's length,
# the lid included) when `outside=true`, else the space inside. Laid out flat
# as finger_box's net (front below the bottom, back above it, the sides beside
# it; the front and back upright, the sides' top edges outward), the lid above
# the back as it lies on the box seen from above (its hinge edge, the back, at
# +y), the cheeks and pins to its right. Members:
# `bottom`, `front`, `back`, `left`, `right`, `lid`, `cheek`, `pin`; the back
# and the sides hold their finger_panel as panel (its size: b.left.panel.outline).
# Only the front's and the lid's top faces (an engraving as drawn) look out: the
# back's, the sides', the cheeks' and the bottom's look in, so a label meant to be
# read outside goes on `front` or `lid`; a side's +y in the net is the box's back.
# Anchor: (cx, cy) is the centre of `bottom`.
def hinged_box(length=120 mm, width=80 mm, height=50 mm, thickness=3 mm, finger=10 mm, pin=0 mm,
               clearance=0.3 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    c = clearance
    gap = 5 mm
    p = pin if pin > 0 mm else t
    lo = length - 2 * t - 2 * c if outside else length + 2 * t  # the body, between the cheeks
    wo = width if outside else width + 2 * t
    hb = height - t if outside else height + t  # the walls, under the lid
    ll = lo + 2 * t + 2 * c                     # the lid, over the cheeks
    assert thickness > 0 mm and height > (3 if outside else 1) * thickness, "the box must be taller than three thicknesses (one, inside)"
    assert finger > 0 mm, "the fingers are more than 0 wide"
    assert clearance >= 0 mm and clearance < thickness, "the clearance is between 0 and the thickness"
    rh = (sqrt(p * p + t * t) + c) / 2  # the cheek's hole: round about the pin's corners
    r = rh + max(t / 3, 0.6 mm)         # the cheek's lobe about the pivot: a wall over 0.5 mm
    b = 2 * r                           # the pivot below the lid, `r` in from the back
    g = b - sqrt(b * b - r * r) + c     # the walls lowered behind the pivot
    run = hb - 2 * t                    # the side walls' back finger joint (finger_panel's)
    q = floor(run / finger)
    odd = q if q % 2 == 1 else q - 1
    n = odd if odd >= 3 else (3 if run >= 3 * t else 1)
    assert (b if n == 1 else run / n) >= b, "the box is too low for its hinge (or the fingers too narrow)"
    assert lo > 4 * t and wo > 2 * r + 2 * t, "the box is too small for its hinge"
    yp = wo / 2 - r  # the pivot
    zp = hb - b
    bottom = finger_panel(width=lo, height=wo, thickness=t, finger=finger, bottom="slots", right="fingers",
                          top="fingers", left="fingers", cx=cx, cy=cy)
    fy = cy - (wo + hb) / 2 - gap
    by = cy + (wo + hb) / 2 + gap
    lx = cx - (lo + hb) / 2 - gap
    rx = cx + (lo + hb) / 2 + gap
    front = finger_panel(width=lo, height=hb, thickness=t, finger=finger, top="flat", cx=cx, cy=fy)
    solid back {
        panel = finger_panel(width=lo, height=hb, thickness=t, finger=finger, bottom="slots", right="slots",
                             top="flat", left="slots", cx=cx, cy=by)
        panel.outline.center == (cx, by)
        hole swing {
            s = Rectangle(center=(cx, by + hb / 2 + (1 mm - g) / 2), width=lo + 2 mm, height=g + 1 mm)
        }
        swing.s.center == (cx, by + hb / 2 + (1 mm - g) / 2)
    }
    # the side walls (the net's x is the product's height), their pin holes and swing notches
    solid left {
        panel = finger_panel(width=hb, height=wo, thickness=t, finger=finger, bottom="slots", right="slots",
                             top="fingers", left="flat", cx=lx, cy=cy)
        panel.outline.center == (lx, cy)
        hole axle {
            s = Rectangle(center=(lx + hb / 2 - zp, cy + yp), width=t, height=p)
        }
        axle.s.center == (lx + hb / 2 - zp, cy + yp)
        hole swing {
            s = Rectangle(center=(lx - hb / 2 + (g - 1 mm) / 2, cy + yp + (r + 1 mm) / 2), width=g + 1 mm,
                          height=r + 1 mm)
        }
        swing.s.center == (lx - hb / 2 + (g - 1 mm) / 2, cy + yp + (r + 1 mm) / 2)
    }
    solid right {
        panel = finger_panel(width=hb, height=wo, thickness=t, finger=finger, bottom="slots", right="flat",
                             top="fingers", left="slots", cx=rx, cy=cy)
        panel.outline.center == (rx, cy)
        hole axle {
            s = Rectangle(center=(rx - hb / 2 + zp, cy + yp), width=t, height=p)
        }
        axle.s.center == (rx - hb / 2 + zp, cy + yp)
        hole swing {
            s = Rectangle(center=(rx + hb / 2 + (1 mm - g) / 2, cy + yp + (r + 1 mm) / 2), width=g + 1 mm,
                          height=r + 1 mm)
        }
        swing.s.center == (rx + hb / 2 + (1 mm - g) / 2, cy + yp + (r + 1 mm) / 2)
    }
    ly = by + hb / 2 + gap + wo / 2
    solid lid {
        plate = Rectangle(center=(cx, ly), width=ll, height=wo)
    }
    bottom.outline.center == (cx, cy)
    front.outline.center == (cx, fy)
    lid.plate.center == (cx, ly)
    Place(bottom, position=(-cx, -cy, 0 mm))
    Place(front, rotation=(90 deg, 0, 0), position=(-cx, t - wo / 2, hb / 2 - fy))
    Place(back, rotation=(90 deg, 0, 0), position=(-cx, wo / 2, hb / 2 - by))
    Place(left, rotation=(0, 90 deg, 0), position=(-lo / 2, -cy, lx + hb / 2))
    Place(right, rotation=(0, -90 deg, 0), position=(lo / 2, -cy, hb / 2 - rx))
    Place(lid, position=(-cx, -ly, hb))
    # the cheeks (left, right) and pins beside the lid; the left cheek is the right one mirrored
    for k in range(2) {
        s = -1 if k == 0 else 1
        hx = cx + ll / 2 + gap + b + k * (2 * r + gap)
        solid cheek {
            web = Rectangle(center=(hx + s * b / 2, ly), width=b, height=2 * r)
            lobe = Circle(center=(hx, ly), radius=r)
            hole bore {
                h = Circle(center=(hx, ly), radius=rh)
            }
            bore.h.center == (hx, ly)
        }
        cheek.web.center == (hx + s * b / 2, ly)
        cheek.lobe.center == (hx, ly)
        px = cx + ll / 2 + gap + t + c / 2
        py = ly - r - gap - p / 2 - k * (p + gap)
        solid pin {
            bar = Rectangle(center=(px, py), width=2 * t + c, height=p)
        }
        pin.bar.center == (px, py)
        Place(cheek, rotation=(0, -s * 90 deg, 0), position=(s * (lo / 2 + c + t), yp - ly, zp - s * hx))
        Place(pin, position=(s * (lo / 2 + c / 2) - px, yp - py, zp - t / 2))
    }
}

# A finger-jointed drawer in an open-front carcass.
# The drawer, an open finger-jointed box with a round finger pull in its front,
# stands on the carcass floor flush with the carcass front, `clearance` from
# the sides, the top and the back. `length` x `depth` x `height` (mm) is the
# carcass's outer size when `outside=true`, else the space inside it.
# Members: `carcass` (bottom, top, back, left, right) and `box` (bottom,
# front, back, left, right); the finger pull is `box.front.pull` (its circle
# `box.front.pull.p`, 20 mm across, or half the front's height if less, at the
# front's centre: a label on the front goes above or below it).
# Anchor: (cx, cy) is the centre of `carcass.bottom`.
def drawer(length=120 mm, depth=100 mm, height=60 mm, thickness=3 mm, finger=10 mm,
           clearance=0.3 mm, outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    c = clearance
    gap = 5 mm
    lo = length if outside else length + 2 * t
    do = depth if outside else depth + t
    ho = height if outside else height + 2 * t
    ld = lo - 2 * t - 2 * c  # the drawer's outer size
    dd = do - t - c
    hd = ho - 2 * t - c
    assert clearance >= 0 mm and clearance < thickness, "the clearance is between 0 and the thickness"
    assert ld > 4 * t and dd > 4 * t and hd > 4 * t, "the carcass must be larger than six thicknesses"
    dp = min(20 mm, hd / 2)  # the finger pull's diameter
    by = cy + (do + ho) / 2 + gap
    ty = cy + do + ho + 2 * gap
    lx = cx - (lo + ho) / 2 - gap
    rx = cx + (lo + ho) / 2 + gap
    assembly carcass {
        bottom = finger_panel(width=lo, height=do, thickness=t, finger=finger, bottom="flat", right="fingers",
                              top="slots", left="fingers", cx=cx, cy=cy)
        top = finger_panel(width=lo, height=do, thickness=t, finger=finger, bottom="flat", right="fingers",
                           top="slots", left="fingers", cx=cx, cy=ty)
        back = finger_panel(width=lo, height=ho, thickness=t, finger=finger, cx=cx, cy=by)
        left = finger_panel(width=ho, height=do, thickness=t, finger=finger, bottom="flat", right="slots",
                            top="slots", left="slots", cx=lx, cy=cy)
        right = finger_panel(width=ho, height=do, thickness=t, finger=finger, bottom="flat", right="slots",
                             top="slots", left="slots", cx=rx, cy=cy)
        bottom.outline.center == (cx, cy)
        top.outline.center == (cx, ty)
        back.outline.center == (cx, by)
        left.outline.center == (lx, cy)
        right.outline.center == (rx, cy)
    }
    # the drawer's net below the carcass's: its bottom, the front below it, the back above it
    dy = cy - do / 2 - gap - hd - gap - dd / 2
    fy = dy - (dd + hd) / 2 - gap
    ky = dy + (dd + hd) / 2 + gap
    dlx = cx - (ld + hd) / 2 - gap
    drx = cx + (ld + hd) / 2 + gap
    assembly box {
        bottom = finger_panel(width=ld, height=dd, thickness=t, finger=finger, bottom="slots", right="fingers",
                              top="slots", left="fingers", cx=cx, cy=dy)
        solid front {
            panel = finger_panel(width=ld, height=hd, thickness=t, finger=finger, top="flat", cx=cx, cy=fy)
            panel.outline.center == (cx, fy)
            hole pull {
                p = Circle(center=(cx, fy), diameter=dp)
            }
            pull.p.center == (cx, fy)
        }
        back = finger_panel(width=ld, height=hd, thickness=t, finger=finger, top="flat", cx=cx, cy=ky)
        left = finger_panel(width=hd, height=dd, thickness=t, finger=finger, bottom="slots", right="slots",
                            top="slots", left="flat", cx=dlx, cy=dy)
        right = finger_panel(width=hd, height=dd, thickness=t, finger=finger, bottom="slots", right="flat",
                             top="slots", left="slots", cx=drx, cy=dy)
        bottom.outline.center == (cx, dy)
        back.outline.center == (cx, ky)
        left.outline.center == (dlx, dy)
        right.outline.center == (drx, dy)
    }
    # assembled: the carcass on z = 0, centered on x = y = 0, the drawer shut on its floor
    Place(carcass.bottom, position=(-cx, -cy, 0 mm))
    Place(carcass.top, position=(-cx, -ty, ho - t))
    Place(carcass.back, rotation=(90 deg, 0, 0), position=(-cx, do / 2, ho / 2 - by))
    Place(carcass.left, rotation=(0, 90 deg, 0), position=(-lo / 2, -cy, lx + ho / 2))
    Place(carcass.right, rotation=(0, -90 deg, 0), position=(lo / 2, -cy, ho / 2 - rx))
    y0 = dd / 2 - do / 2  # the drawer's middle
    Place(box.bottom, position=(-cx, y0 - dy, t))
    Place(box.front, rotation=(90 deg, 0, 0), position=(-cx, t - do / 2, t + hd / 2 - fy))
    Place(box.back, rotation=(90 deg, 0, 0), position=(-cx, dd - do / 2, t + hd / 2 - ky))
    Place(box.left, rotation=(0, 90 deg, 0), position=(-ld / 2, y0 - dy, t + dlx + hd / 2))
    Place(box.right, rotation=(0, -90 deg, 0), position=(ld / 2, y0 - dy, t + hd / 2 - drx))
}

import "std/plates.aidl"

# A rounded box whose wall bends round on living hinges.
# The base and the lid are plates with corners of `radius`, each with a
# `lip` glued on (under the lid) that fits inside the wall with `clearance`
# all round. The wall stands on the base between them: a strip as long as
# the wall's middle line (the straight sides and four quarter arcs), its ends
# meeting mid-front, with a `living_hinge` over each arc. `length` x `width`
# x `height` (mm) and `radius` are outer sizes when `outside=true`, else
# inner (the height between the base's lip and the lid's). Assembled, the
# wall is shown bent round the corners (`Bend`).
# Members: `base`, `lid`, `lip` (base's, lid's), `wall`.
# Anchor: (cx, cy) is the centre of `base`.
def flex_box(length=120 mm, width=80 mm, height=50 mm, radius=20 mm, thickness=3 mm, clearance=0.3 mm,
             outside=true, cx=0 mm, cy=0 mm) -> assembly {
    t = thickness
    c = clearance
    gap = 5 mm
    lo = length if outside else length + 2 * t
    wo = width if outside else width + 2 * t
    ho = height if outside else height + 4 * t  # inside: between the two lips
    ro = radius if outside else radius + t
    assert clearance >= 0 mm and clearance < thickness, "the clearance is between 0 and the thickness"
    assert ro >= 2 * t + c, "the radius must be at least twice the thickness"
    assert 2 * ro <= wo and 2 * ro <= lo, "the radius is at most half the width and the length"
    hw = ho - 2 * t  # the wall, between the base and the lid
    assert hw > 2 * t, "the box must be taller than four thicknesses"
    rn = ro - t / 2  # the wall's middle line at the corners
    arc = pi * rn / 2
    ls = lo - 2 * ro  # the straight sides
    ws = wo - 2 * ro
    run = 2 * ls + 2 * ws + 4 * arc  # the wall's length
    solid base {
        plate = RoundedRectangle(center=(cx, cy), width=lo, height=wo, corner_radius=ro)
    }
    solid lid {
        plate = RoundedRectangle(center=(cx + lo + gap, cy), width=lo, height=wo, corner_radius=ro)
    }
    base.plate.center == (cx, cy)
    lid.plate.center == (cx + lo + gap, cy)
    for k in range(2) {
        ky = cy + wo / 2 + gap + (wo - 2 * t - 2 * c) / 2
        kx = cx + k * (lo + gap)
        solid lip {
            plate = RoundedRectangle(center=(kx, ky), width=lo - 2 * t - 2 * c, height=wo - 2 * t - 2 * c,
                                     corner_radius=ro - t - c)
        }
        lip.plate.center == (kx, ky)
        Place(lip, position=(-kx, -ky, t if k == 0 else ho - 2 * t))
    }
    # the wall from mid-front round (front, right, back, left): the back's middle is the strip's
    wx = cx - lo / 2 + run / 2
    wy = cy - wo / 2 - gap - hw / 2
    us = [ls / 2 + arc / 2, ls / 2 + arc + ws + arc / 2, run - ls / 2 - arc - ws - arc / 2, run - ls / 2 - arc / 2]
    solid wall {
        strip = Rectangle(center=(wx, wy), width=run, height=hw)
        for u in us {
            flex = living_hinge(width=arc, height=hw, cx=cx - lo / 2 + u, cy=wy)
            Fixed(flex)
        }
    }
    wall.strip.center == (wx, wy)
    Place(base, position=(-cx, -cy, 0 mm))
    Place(lid, position=(-cx - lo - gap, -cy, ho - t))
    # assembled: the strip's start stands mid-front, its top face inward, and bends round each
    # corner over its hinge (inside radius ro - t: its outer face on the base's outline)
    Place(wall, rotation=(90 deg, 0, 180 deg), position=(cx - lo / 2, -wo / 2, t + hw / 2 - wy))
    for u in us {
        Bend(wall, at=cx - lo / 2 + u, angle=90 deg, radius=ro - t)
    }
}
