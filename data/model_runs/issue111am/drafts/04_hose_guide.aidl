# Request (garden): a hose guide for the corner of a flower bed, 6 mm exterior ply, two parts.
# A stake 40 mm wide, 300 mm tall overall, its bottom 60 mm tapering to a point, and a
# cross-halving slot 20 mm deep from the middle of its top. A crossbar 160 x 40 mm with a
# 20 x 30 mm horn standing up at each end (R8 rounded tops) to keep the hose from riding off,
# halved 20 mm up from the middle of its bottom edge onto the stake. "HOSE" engraved in
# 10 mm strokes down the stake, 40 mm below the crossbar.
units mm
thickness 6 mm
import "std/joints.aidl"

param stake_h = 300 mm, min = 200, max = 500
param w = 40 mm, min = 30, max = 60

assembly hose_guide {
    solid stake {
        shaft = Rectangle(corner=(-w / 2, -stake_h / 2 + 60), opposite=(w / 2, stake_h / 2))
        tip = Triangle(center=(0, -stake_h / 2 + 30), base=w, height=60, rotation=180 deg)
        h = cross_halving(depth=20 mm, thickness=6 mm, cx=0 mm, cy=stake_h / 2)
        drawing label {
            t = Text("HOSE", (0, 60), size=10, rotation=-90, valign="middle")
        }
        label.bb.top == shaft.bb.top - 40
        assert shaft.bb.top - tip.bb.bottom == 300 mm, "stake 300 tall"
        assert tip.height == 60 mm, "60 mm point"
    }
    solid crossbar {
        bar = Rectangle(center=(120, 0), width=160, height=40)
        hornL = RoundedRectangle(bottom_left=(40, 20), width=20, height=30,
                                 corner_radii=[8, 8, 0, 0])
        hornR = RoundedRectangle(bottom_left=(180, 20), width=20, height=30,
                                 corner_radii=[8, 8, 0, 0])
        AlignLeft(hornL, bar)
        AlignRight(hornR, bar)
        # FIX after the first valid program: gap=-1 (written to be sure the horns merge) left them
        # standing 29 mm above the bar, not the requested 30; touching shapes merge anyway.
        Above(hornL, bar)
        Above(hornR, bar)
        assert hornL.bb.top - bar.bb.top == 30 mm, "horns stand 30 mm up"
        h2 = cross_halving(depth=20 mm, thickness=6 mm, rotation=180 deg, cx=120 mm, cy=-20 mm)
        assert bar.width == 160 mm and bar.height == 40 mm, "crossbar size"
    }
    assert stake.h.depth + crossbar.h2.depth == 40 mm, "halvings add up to the 40 mm bar"
}
