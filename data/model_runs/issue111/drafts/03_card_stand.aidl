# Business-card stand from two cross-halved pieces of 3 mm sheet: each piece a trapezoid
# 100 mm along the bottom, 70 mm along the top, 45 mm tall. The front piece has a
# cross-halving slot from the middle of its top edge, the back piece one from the middle of
# its bottom edge, each 22.5 mm deep (half the height) and 3 mm + 0.2 mm clearance wide.
# The front piece also has a 3.5 mm wide, 12 mm deep card groove 15 mm left of center.
# Parts laid out side by side, 10 mm apart.

import "std/joints.aidl"

thickness 3 mm

assembly card_stand {
    solid front {
        body = Trapezoid(center=(0, 0), bottom_width=100, top_width=70, height=45)
        joint = cross_halving(depth=22.5 mm, thickness=3 mm, clearance=0.2 mm, cx=0 mm, cy=22.5 mm)
        hole groove {
            g = Rectangle(center=(-15, 16.5), width=3.5, height=12)
        }
        AlignTop(groove, body)
    }
    solid back {
        body = Trapezoid(center=(110, 0), bottom_width=100, top_width=70, height=45)
        joint = cross_halving(depth=22.5 mm, thickness=3 mm, clearance=0.2 mm, rotation=180 deg,
                              cx=110 mm, cy=-22.5 mm)
    }
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    assert front.joint.cut.bb.height == 22.5 mm and back.joint.cut.bb.height == 22.5 mm, "slots half the height"
    assert front.joint.cut.bb.width == 3.2 mm, "slot 3.2 mm wide"
    assert front.body.bb.height == 45 mm and front.body.bb.width == 100 mm, "piece 100 x 45"
    assert front.groove.g.height == 12 mm, "groove 12 mm deep"
}
