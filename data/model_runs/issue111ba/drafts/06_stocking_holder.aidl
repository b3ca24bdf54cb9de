# Request (holidays): a Christmas stocking holder for the mantelpiece, one per child, from
# 6 mm birch ply. A side-profile hanger: a foot 120 mm deep and 20 mm tall lying on the
# mantel shelf, a 12 mm strip going 50 mm down the mantel's front face, and at its bottom a
# J hook (12 mm wide band, 15 mm centre radius) curling forward for the stocking's loop. The
# child's name "EMMA" in 50 mm bold letters stands across the foot, its letters sitting 3 mm
# into a 20 mm rail as wide as the word; name and hanger are cross-halved together, 10 mm
# each, the halving in the middle of the foot and of the word, so the rail stands on the
# shelf too.

units mm
thickness 6 mm
kerf 0.15 mm

import "std/joints.aidl"

ply = 6 mm
foot_d = 120 mm
foot_h = 20 mm
drop = 50 mm
strip_w = 12 mm
hook_r = 15 mm
letter_h = 50 mm
rail_h = 20 mm
sink = 3 mm

assembly stocking_holder {
    solid hanger {
        foot = Rectangle(bottom_left=(0, 0), width=foot_d, height=foot_h)
        strip = Rectangle(bottom_left=(-strip_w, -drop), width=strip_w, height=drop + foot_h)
        hook = ArcSlot(center=(-strip_w / 2 - hook_r, -drop), radius=hook_r,
                       start_angle=180 deg, end_angle=360 deg, width=strip_w)
        Fixed(foot)
        halving = cross_halving(depth=foot_h / 2, thickness=ply, clearance=0.1 mm,
                                cx=foot_d / 2, cy=foot_h)
    }
    solid name {
        word = Text("EMMA", position=(0, rail_h - sink), size=letter_h, font="sans:Bold")
        rail = Rectangle(center=(word.center.x, rail_h / 2), width=word.bb.width, height=rail_h)
        Fixed(word)
        halving = cross_halving(depth=rail_h / 2, thickness=ply, clearance=0.1 mm,
                                rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    # flat on the sheet
    RightOf(name, hanger, gap=10)
    AlignBottom(name, hanger)

    # assembled: x along the mantel, y into the shelf from its front edge, z up
    Place(hanger, rotation=(90 deg, 0, 90 deg), position=(-ply / 2, 0, 0))
    Place(name, rotation=(90 deg, 0, 0), position=(0, foot_d / 2 + ply / 2, 0))

    assert hanger.foot.width == 120 mm and hanger.foot.height == 20 mm, "foot 120 x 20"
    assert hanger.foot.bb.bottom - hanger.strip.bb.bottom == 50 mm, "strip 50 down the face"
    assert hanger.hook.radius == 15 mm and hanger.hook.width == 12 mm, "hook 15 radius, 12 band"
    assert name.word.size == 50 mm, "50 mm letters"
    assert name.word.bb.bottom - name.rail.bb.top <= -3 mm + 0.5 mm, "letters 3 mm into the rail"
    assert name.rail.bb.width == name.word.bb.width, "rail as wide as the word"
    assert hanger.halving.depth + name.halving.depth == foot_h, "halvings meet"
    assert abs(name.halving.cut.bb.center_x - name.rail.bb.center_x) < 2 mm, "halving in the middle of the word"
}
