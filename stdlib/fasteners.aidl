# AIDL standard library: holes for metric screws and nuts, M2 to M20.
#   import "std/fasteners.aidl"
# Clearance holes: ISO 273 (fine, medium, coarse series). Nuts: ISO 4032
# hexagon nuts, style 1 (width across flats s, thickness m max).

# The table, one entry per size (index with `metric_index`'s rule).
metric_sizes = [2, 2.5, 3, 3.5, 4, 5, 6, 8, 10, 12, 16, 20]
clearance_fine = [2.2 mm, 2.7 mm, 3.2 mm, 3.7 mm, 4.3 mm, 5.3 mm, 6.4 mm, 8.4 mm, 10.5 mm, 13 mm,
                  17 mm, 21 mm]
clearance_medium = [2.4 mm, 2.9 mm, 3.4 mm, 3.9 mm, 4.5 mm, 5.5 mm, 6.6 mm, 9 mm, 11 mm, 13.5 mm,
                    17.5 mm, 22 mm]
clearance_coarse = [2.6 mm, 3.1 mm, 3.6 mm, 4.2 mm, 4.8 mm, 5.8 mm, 7 mm, 10 mm, 12 mm, 14.5 mm,
                    18.5 mm, 24 mm]
nut_across_flats = [4 mm, 5 mm, 5.5 mm, 6 mm, 7 mm, 8 mm, 10 mm, 13 mm, 16 mm, 18 mm, 24 mm, 30 mm]
nut_thickness = [1.6 mm, 2 mm, 2.4 mm, 2.8 mm, 3.2 mm, 4.7 mm, 5.2 mm, 6.8 mm, 8.4 mm, 10.8 mm,
                 14.8 mm, 18 mm]

# A through hole for a metric screw (ISO 273). `size` 3 is M3; `fit`
# "fine" (also "close"), "medium" (also "normal") or "coarse" (also "loose").
# M3 medium is 3.4 mm. Member: `c` (the circle).
# Anchor: (cx, cy) is the centre of `c`.
def clearance_hole(size=3, fit="medium", cx=0 mm, cy=0 mm) -> hole {
    found = [i for i in range(len(metric_sizes)) if metric_sizes[i] == size]
    assert len(found) == 1, "`size` is not a metric size: 2, 2.5, 3, 3.5, 4, 5, 6, 8, 10, 12, 16 or 20 (M2 to M20)"
    fine = fit == "fine" or fit == "close"
    medium = fit == "medium" or fit == "normal"
    coarse = fit == "coarse" or fit == "loose"
    assert (1 if fine or medium or coarse else 0) == 1, "fit is \"fine\", \"medium\" or \"coarse\""
    i = found[0] if len(found) == 1 else 2  # (after the error above: go on as M3)
    d = clearance_fine[i] if fine else (clearance_medium[i] if medium else clearance_coarse[i])
    c = Circle(center=(cx, cy), diameter=d)
    Fixed(c.center)
}

# A hexagonal cut-out that holds a metric nut (ISO 4032) from turning. It is
# across flats s of the nut of `size` (5.5 mm for M3) plus `clearance`, flats
# at top and bottom (turn with `rotation`). Member: `hex` (a RegularPolygon).
# Anchor: (cx, cy) is the centre of `hex`; rotation 0: flats at top and bottom.
def nut_trap(size=3, clearance=0 mm, rotation=0 deg, cx=0 mm, cy=0 mm) -> hole {
    found = [i for i in range(len(metric_sizes)) if metric_sizes[i] == size]
    assert len(found) == 1, "`size` is not a metric size: 2, 2.5, 3, 3.5, 4, 5, 6, 8, 10, 12, 16 or 20 (M2 to M20)"
    hex = RegularPolygon(center=(cx, cy), across_flats=nut_across_flats[found[0] if len(found) == 1 else 2] + clearance,
                         sides=6, rotation=rotation)
    Fixed(hex.center)
}

# A T-slot: a screw and its nut entering a panel from its edge (the joint of
# laser-cut boxes). For a screw of `size`: a slot as wide as the medium clearance hole running
# `length` from the edge (the mouth at (cx, cy), running toward -y when
# `rotation` is 0), crossed by a pocket for the nut (across flats wide, nut
# thickness deep plus `clearance`) at `nut_depth` from the edge; the slot's
# run 1 mm past the edge, `overrun`, counts in no box. Members: `slot` (within
# the panel), `overrun`, `nut` (Rectangles).
# Anchor: (cx, cy) is the middle of its mouth on the edge; rotation 0: the slot runs toward -y.
def t_slot(size=3, length=12 mm, nut_depth=6 mm, clearance=0.1 mm, rotation=0 deg,
           cx=0 mm, cy=0 mm) -> hole {
    found = [i for i in range(len(metric_sizes)) if metric_sizes[i] == size]
    assert len(found) == 1, "`size` is not a metric size: 2, 2.5, 3, 3.5, 4, 5, 6, 8, 10, 12, 16 or 20 (M2 to M20)"
    i = found[0] if len(found) == 1 else 2  # (after the error above: go on as M3)
    assert nut_depth + nut_thickness[i] / 2 < length, "the nut pocket must end before the slot does"
    slot = Rectangle(center=(cx + sin(rotation) * length / 2, cy - cos(rotation) * length / 2),
                     width=clearance_medium[i], height=length, rotation=rotation)
    overrun = Rectangle(center=(cx + sin(rotation) * (length - 1 mm) / 2, cy - cos(rotation) * (length - 1 mm) / 2),
                        width=clearance_medium[i], height=length + 1 mm, rotation=rotation, overrun=true)
    nut = Rectangle(center=(cx + sin(rotation) * nut_depth, cy - cos(rotation) * nut_depth),
                    width=nut_across_flats[i] + clearance, height=nut_thickness[i] + clearance,
                    rotation=rotation)
    Fixed(slot.center)
    Fixed(overrun.center)
    Fixed(nut.center)
}
