# Request (home): a fireside tool stand in 12 mm birch ply for a set of four
# 50 cm tools (poker, brush, shovel, tongs) that hang by their handle loops.
# Three parts, glued:
# - an upright 80 mm wide and 590 mm tall overall, its two top corners rounded
#   10 mm, two 20 mm tabs on its bottom edge (12 mm long) into the base, a
#   cross-halving slot 20 mm deep down from the middle of its top edge, and
#   "HEARTH" engraved filled in bold serif, 40 mm letters, running up its face;
# - a hook bar 260 mm long and 40 mm tall, halved 20 mm up from the middle of its
#   bottom edge onto the upright, with four hook notches in its top edge, 10 mm
#   wide and 15 mm deep with round bottoms, at 45 mm and 100 mm either side of
#   its middle;
# - a round base 260 mm across with two mortises for the upright's tabs
#   (0.1 mm clearance) at its centre.

import "std/joints.aidl"

t = 12 mm
thickness t

assembly stand {
    solid upright {
        body = Rectangle(bottom_left=(0, 0), width=80, height=590)
        Fillet([body.top_left, body.top_right], 10)
        feet = tab_and_slot(part="tab", length=80 mm, thickness=t, tabs=2, tab=20 mm,
                            screw=0, rotation=180 deg, cx=40 mm, cy=0 mm)
        top_slot = cross_halving(depth=20 mm, thickness=t, clearance=0.1 mm,
                                 cx=40 mm, cy=590 mm)
        drawing name {
            word = Text("HEARTH", position=(40, 300), size=40, rotation=90,
                        valign="middle", font="serif:Bold", fill=true)
        }
        assert len(feet.gap) == 3, "two tabs leave three gaps"
        assert body.bb.height == 590 mm, "590 mm tall overall"
        assert distance(name, top_slot) >= 10 mm, "the name clears the halving slot"
    }

    solid bar {
        body = Rectangle(center=(200, 300), width=260, height=40)
        half = cross_halving(depth=20 mm, thickness=t, clearance=0.1 mm,
                             rotation=180 deg, cx=200 mm, cy=280 mm)
        hole hooks {
            for x in [-100, -45, 45, 100] {
                n = Slot(center=(200 + x, 320), length=30, width=10, rotation=90)
            }
        }
        assert len(hooks.n) == 4, "four hook notches"
        assert body.bb.width == 260 mm, "260 mm long"
        assert body.bb.top - hooks.n[0].bb.bottom == 15 mm, "notches 15 mm deep"
        assert hooks.n[2].center.x - hooks.n[1].center.x == 90 mm, "inner notches 45 mm either side"
        assert hooks.n[3].center.x - hooks.n[0].center.x == 200 mm, "outer notches 100 mm either side"
        assert distance(hooks, half) >= 20 mm, "the notches clear the upright"
    }

    solid base {
        disc = Circle(center=(400, 150), diameter=260)
        mortise = tab_and_slot(part="slot", length=80 mm, thickness=t, tabs=2, tab=20 mm,
                               screw=0, clearance=0.1 mm, cx=400 mm, cy=150 mm)
        assert len(mortise.slot) == 2, "two mortises"
    }

    # FIX after the first valid program: the bar was written over the upright
    # (W0511); lay the parts out side by side
    RightOf(bar, upright, gap=10)
    AlignTop(bar, upright)
    RightOf(base, upright, gap=10)
    Below(base, bar, gap=10)
}
