# Request: a gear carabiner (NOT for climbing) for hanging a mug, a lamp and keys off my
# rucksack, cut from 4 mm acetal (POM) so the gate can flex. Outside 50 x 84 mm with R20
# corners; the inside opening 34 x 64 mm with R12 corners, set 2 mm above centre, so the side
# and top walls are 8 mm and the bottom 12 mm; a 5 mm lanyard hole in the middle of the bottom
# bar. The right wall is cut away from 12 mm below centre to 22 mm above it; a flexing gate
# 3 mm wide grows from the wall's lower end up to 2 mm short of the nose, and a lip on the
# nose 2 mm thick, reaching 6 mm down outside the gate's tip with 0.5 mm clearance, stops the
# gate opening outward (it only swings in). "GEAR ONLY" engraved along the spine, at most
# 38 mm long.
# FIX after the first valid program: the opening hole, declared in `carabiner`, cut away the
# gate and the lip too (W0506 twice: no gate, an open C). The frame and its holes now sit in a
# solid of their own, beside the gate and the lip, as the hint said.

units mm
thickness 4 mm

solid carabiner {
    solid frame {
        body = RoundedRectangle(center=(0, 0), width=50, height=84, corner_radius=20)
        hole inside { r = RoundedRectangle(center=(0, 2), width=34, height=64, corner_radius=12) }
        hole lanyard { c = Circle(center=(0, -36), diameter=5) }
        # the gate opening: the right wall (x 17..25) removed from y -12 to 22
        hole opening { r = Rectangle(corner=(16, -12), opposite=(26, 22)) }
    }
    # the gate: a 3 mm strip from the wall below the opening up to 2 mm short of the nose
    solid gate { g = Rectangle(corner=(19.5, -13), opposite=(22.5, 20)) }
    # the lip on the nose, outside the gate's tip
    solid lip { l = Rectangle(corner=(23, 16), opposite=(25, 22)) }
    drawing label {
        w = Text("GEAR ONLY", position=(-21, 2), size=4, rotation=90, valign="middle", max_width=38)
    }

    # the request's numbers
    assert frame.body.width == 50 mm and frame.body.height == 84 mm, "50 x 84 outside"
    assert frame.inside.r.width == 34 mm and frame.inside.r.height == 64 mm, "34 x 64 inside"
    assert frame.inside.r.bb.left - frame.body.bb.left == 8 mm, "8 mm side walls"
    assert frame.body.bb.top - frame.inside.r.bb.top == 8 mm, "8 mm top wall"
    assert frame.inside.r.bb.bottom - frame.body.bb.bottom == 12 mm, "12 mm bottom bar"
    assert abs(frame.lanyard.c.center.y - (frame.body.bb.bottom + frame.inside.r.bb.bottom) / 2) < 0.01 mm,
        "lanyard hole in the middle of the bottom bar"
    assert gate.g.width == 3 mm, "3 mm gate"
    assert frame.opening.r.bb.top - gate.g.bb.top == 2 mm, "gate 2 mm short of the nose"
    assert lip.l.bb.left - gate.g.bb.right == 0.5 mm, "0.5 mm clearance outside the tip"
    assert gate.g.bb.top - lip.l.bb.bottom >= 4 mm, "the lip overlaps the tip"
    assert lip.l.bb.height == 6 mm and lip.l.bb.width == 2 mm, "lip 2 thick, 6 down"
    assert gate.g.bb.left >= frame.inside.r.bb.right, "the gate stands in the wall's line"
    assert label.bb.height <= 38 mm, "GEAR ONLY at most 38 long"
    assert label.bb.left >= frame.body.bb.left + 1 mm and label.bb.right <= frame.inside.r.bb.left - 1 mm,
        "the label on the spine"
}
