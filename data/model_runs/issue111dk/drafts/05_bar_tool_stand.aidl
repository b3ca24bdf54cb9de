# Request (parties): a home-bar tool stand for cocktail evenings, 6 mm walnut ply. A base
# 260 x 120 mm (8 mm corner radius) and a shelf of the same size 80 mm above it (clear),
# carried by two 100 mm deep end panels 10 mm in from the ends, each glued in by two 20 mm
# tabs top and bottom through mortises. The shelf has holes the tools drop through to stand
# on the base: a 92 mm shaker, a 48 mm jigger, three 12 mm bar spoons in a row across, a 32 mm
# muddler; each labelled in single strokes along the shelf's front strip (SHAKER, JIGGER,
# SPOONS, MUDDLER). Each end panel has a martini-glass silhouette cut through it.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
plate_l = 260 mm
plate_d = 120 mm
clear_h = 80 mm
end_d = 100 mm
end_x = plate_l / 2 - 10 mm - t / 2     # the end panels' mid-planes, 10 mm in from the ends

def plate(holes=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate_l, height=plate_d, corner_radius=8)
    for s in [-1, 1] {
        mort = tab_and_slot(part="slot", length=end_d, thickness=t, tabs=2, tab=20 mm,
                            screw=0, cx=s * end_x, cy=0, rotation=90 deg)
    }
    if holes {
        hole shaker { c = Circle(center=(-62, 0), diameter=92) }
        hole jigger { c = Circle(center=(14, 0), diameter=48) }
        hole spoons {
            for y in [-30, 0, 30] {
                c = Circle(center=(55, y), diameter=12)
            }
        }
        hole muddler { c = Circle(center=(88, 0), diameter=32) }
        drawing labels {
            l1 = Text("SHAKER", position=(-62, -55), size=5)
            l2 = Text("JIGGER", position=(14, -55), size=5)
            # FIX after the first valid program: W0513, "SPOONS" and "MUDDLER" read as one
            l3 = Text("SPOONS", position=(55, -55), size=4.5)
            l4 = Text("MUDDLER", position=(91, -55), size=4.5)
        }
    }
}

def end_panel() -> solid {
    body = Rectangle(bottom_left=(-end_d / 2, -t), width=end_d, height=clear_h + 2 * t)
    # FIX after the first valid program: W0502, the tab joints cut nothing (and W0517, the
    # uncut ends collided with base and shelf): at rotation 0 the panel lies BELOW the edge,
    # so the bottom edge (panel above it) takes 180 deg and the top edge 0
    bottom_tabs = tab_and_slot(part="tab", length=end_d, thickness=t, tabs=2, tab=20 mm,
                               screw=0, cx=0, cy=-t, rotation=180 deg)
    top_tabs = tab_and_slot(part="tab", length=end_d, thickness=t, tabs=2, tab=20 mm,
                            screw=0, cx=0, cy=clear_h + t, rotation=0)
    hole glass {
        bowl = Triangle(center=(0, 56), base=40, height=24, rotation=180 deg)
        stem = Rectangle(center=(0, 34), width=3, height=22)
        foot = Ellipse(center=(0, 23), rx=12, ry=2.5)
    }
}

assembly bar_stand {
    base = plate(holes=false)
    shelf = plate(holes=true)
    left_end = end_panel()
    right_end = end_panel()

    # flat on the sheet
    Above(shelf, base, gap=10)
    AlignLeft(shelf, base)
    RightOf(left_end, base, gap=10)
    AlignBottom(left_end, base)
    Above(right_end, left_end, gap=10)
    AlignLeft(right_end, left_end)

    # in 3D: the base on the bar, the ends on it, the shelf on the ends
    Place(base, position=(0, 0, 0), face="up")
    Place(shelf, position=(0, 0, t + clear_h), face="up")
    Place(left_end, position=(-end_x + t / 2, 0, t), face="left", up="up")
    Place(right_end, position=(end_x - t / 2, 0, t), face="right", up="up")

    # the request's numbers
    assert base.body.bb.width == 260 mm and base.body.bb.height == 120 mm, "260 x 120"
    assert left_end.body.bb.height - 2 * 6 mm == 80 mm, "80 mm clear between base and shelf"
    assert left_end.body.bb.width == 100 mm, "ends 100 deep"
    assert shelf.body.bb.right - shelf.mort[1].bb.right == 10 mm, "ends 10 mm in from the ends"
    assert shelf.shaker.c.diameter == 92 mm and shelf.jigger.c.diameter == 48 mm, "shaker, jigger"
    assert len(shelf.spoons.c) == 3 and shelf.spoons.c[0].diameter == 12 mm, "three spoons"
    assert shelf.muddler.c.diameter == 32 mm, "muddler"
}
