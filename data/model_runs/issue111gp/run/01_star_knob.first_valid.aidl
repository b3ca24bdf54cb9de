# Request: a five-lobed star knob for my bench jig hold-downs. It captures an M8 hex bolt
# (head 13 mm across flats) and is glued up from three layers of 6 mm birch ply, 18 mm tall.
# Every layer is a 60 mm disc with five 16 mm scallops cut into its rim (scallop centres on a
# 31 mm radius, evenly spaced, one at the top), the corners where scallop meets rim rounded
# 2 mm, and two 3 mm dowel holes 15 mm either side of the centre to line the layers up.
# Bottom layer: a 9 mm clearance hole for the M8 shank. Middle layer: a hex trap for the bolt
# head, 13 mm across flats plus 0.2 mm clearance. Top layer: a closed cap with "M8" engraved
# filled in the middle, 10 mm tall.

import "std/fasteners.aidl"

t = 6 mm
thickness t

param knob_d = 60 mm, min = 50 mm, max = 80 mm
param lobes = 5, min = 3, max = 8
scallop_d = 16 mm
scallop_r = 31 mm
dowel_off = 15 mm

def layer(kind="bottom") -> solid {
    disc = Circle(center=(0, 0), diameter=knob_d)
    hole scallop { c = Circle(center=(0, scallop_r), diameter=scallop_d) }
    ring = CircularPattern(scallop, lobes, (0, 0))
    hole dowels {
        a = Circle(center=(-dowel_off, 0), diameter=3 mm)
        b = Circle(center=(dowel_off, 0), diameter=3 mm)
    }
    if kind == "bottom" {
        bore = clearance_hole(size=8)
    } elif kind == "middle" {
        trap = nut_trap(size=8, clearance=0.2 mm)
    } else {
        drawing label {
            word = Text("M8", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }
    # round only where a scallop meets the rim (never the hex trap's corners)
    Fillet([[disc, ring[i].c] for i in range(lobes)], 2 mm)
}

assembly knob {
    bottom = layer(kind="bottom")
    middle = layer(kind="middle")
    top = layer(kind="top")
    RightOf(middle, bottom, gap=6)
    AlignTop(middle, bottom)
    RightOf(top, middle, gap=6)
    AlignTop(top, middle)

    # glued stack: bottom on the work, middle holds the head, cap on top
    Place(bottom, position=(0, 0, 0), face="up")
    Place(middle, position=(0, 0, t), face="up")
    Place(top, position=(0, 0, 2 * t), face="up")

    assert bottom.disc.diameter == 60 mm, "60 mm knob"
    assert len(bottom.ring) == 5, "five scallops"
    assert bottom.ring[0].c.diameter == 16 mm, "16 mm scallops"
    assert distance(bottom.ring[0].c.center, bottom.disc.center) == 31 mm, "scallops on a 31 mm radius"
    assert bottom.ring[0].c.center.y - bottom.disc.center.y == 31 mm, "one scallop at the top"
    assert bottom.bore.c.diameter == 9 mm, "9 mm clearance for the M8 shank"
    assert middle.trap.hex.across_flats == 13.2 mm, "13 mm head plus 0.2 mm"
    assert distance(middle.dowels.a.center, middle.dowels.b.center) == 30 mm, "dowels 15 mm either side"
    assert 3 * t == 18 mm, "18 mm tall"
    assert top.label.word.size == 10 mm, "M8 10 mm tall"
    assert distance(top.label.word.position, top.disc.center) == 0 mm, "M8 in the middle"
}
