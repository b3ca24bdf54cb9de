# Cross-halved Easter table egg (parties / spring table): two egg panels of 3 mm ply
# slotted into each other at right angles so the egg stands on the table. Each panel is an
# ellipse 100 mm wide and 130 mm tall with its bottom cut flat 8 mm above the lowest
# point (panel height 122 mm). Panel A has a slot from the top down, panel B a slot from
# the flat bottom up, each 61 mm deep (half of 122) and 3.1 mm wide (3 mm ply + 0.1 mm),
# on the centre line. Each panel has an engraved zig-zag band 80 mm long, 10 mm from peak
# to peak, 8 teeth (A: 20 mm below the ellipse centre, B: 25 mm above it, clear of the
# slots) and A has "EASTER" engraved 8 mm high, 40 mm below the ellipse centre.
# The two panels lie 10 mm apart on the sheet.

units mm
thickness 3 mm

import "std/joints.aidl"

param ply = 3 mm, min = 2 mm, max = 6 mm
param play = 0.1 mm, min = 0 mm, max = 0.4 mm

egg_w = 100 mm
egg_h = 130 mm
trim = 8 mm
panel_h = egg_h - trim
half = panel_h / 2

def egg_panel(from_top=true, band_y=0 mm, word="") -> solid {
    oval = Ellipse(center=(0, 0), rx=egg_w / 2, ry=egg_h / 2, construction=true)
    keep = Rectangle(bottom_left=(-egg_w / 2 - 1, -egg_h / 2 + trim), width=egg_w + 2,
                     height=egg_h, construction=true)
    shape = Intersect(oval, keep)
    if from_top {
        slot = cross_halving(depth=half, thickness=ply, clearance=play, cx=0 mm, cy=egg_h / 2)
    } else {
        slot = cross_halving(depth=half, thickness=ply, clearance=play, rotation=180 deg,
                             cx=0 mm, cy=-egg_h / 2 + trim)
    }
    drawing band {
        zig = Polyline([(-40 + i * 5, band_y + (5 if i % 2 == 0 else -5)) for i in range(17)])
        if word != "" {
            label = Text(word, position=(0, -40), size=8)
        }
    }
}

assembly easter_egg {
    a = egg_panel(from_top=true, band_y=-20 mm, word="EASTER")
    b = egg_panel(from_top=false, band_y=25 mm)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    assert a.shape.bb.width == 100 mm, "egg 100 mm wide"
    assert a.shape.bb.height == 122 mm, "panel 122 mm tall (130 with 8 mm cut flat)"
    assert b.shape.bb.height == 122 mm, "panel B 122 mm tall"
    assert a.slot.cut.bb.height == 61 mm, "A's slot 61 mm deep"
    assert b.slot.cut.bb.height == 61 mm, "B's slot 61 mm deep"
    assert a.slot.cut.bb.width == 3.1 mm, "slot 3.1 mm wide"
    assert a.slot.cut.bb.top == a.shape.bb.top, "A's slot opens at the top"
    assert b.slot.cut.bb.bottom == b.shape.bb.bottom, "B's slot opens at the bottom"
    assert a.slot.cut.bb.center_x == a.shape.bb.center_x, "slot on the centre line"
    assert a.band.zig.bb.width == 80 mm, "band 80 mm long"
    assert a.band.zig.bb.height == 10 mm, "band 10 mm peak to peak"
    assert len(a.band.zig.points) == 2 * 8 + 1, "8 teeth (8 valleys between 9 peaks)"
    assert b.shape.bb.left - a.shape.bb.right == 10 mm, "10 mm apart on the sheet"
    assert a.band.label.size == 8 mm, "EASTER 8 mm"
}
