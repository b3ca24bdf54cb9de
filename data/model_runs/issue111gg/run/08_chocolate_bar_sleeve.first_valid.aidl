# Request: a gift sleeve for a 100 g chocolate bar (80 x 12 mm in section, 160 mm
# long in its wrapper), 3 mm birch ply. An open-ended finger-jointed tube 120 mm
# long, 88 x 20 mm outside (inside 82 x 14: 1 mm room each way round the bar),
# 10 mm fingers: a top and a bottom panel with fingers along their long edges,
# two 120 x 20 side walls slotted to take them. The top panel has "FOR MIA" cut
# through as stencil letters (bold sans, 18 mm capitals, at most 100 mm wide) so
# the wrapper shows through, centred 10 mm above the middle; under it "with love"
# engraved (filled, italic serif, 8 mm) and a small heart (about 17 mm wide) cut
# out to its right, 6 mm from the words, on one line centred on the panel 22 mm
# below the middle.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

len_ = 120 mm
out_w = 88 mm
out_h = 20 mm

assembly sleeve {
    solid top {
        panel = finger_panel(width=len_, height=out_w, thickness=t, finger=10 mm,
                             bottom="fingers", right="flat", top="fingers", left="flat")
        hole name {
            n = Text("FOR MIA", position=(0, 10), size=18, font="sans:Bold", valign="middle",
                     stencil=true, max_width=100 mm)
        }
        drawing love {
            w = Text("with love", position=(-10, -22), size=8, font="serif:Italic",
                     valign="middle", fill=true)
        }
        hole heart {
            l = Hull(Circle(center=(-4, 2.5), radius=4.5), Point(0, -8))
            r = Hull(Circle(center=(4, 2.5), radius=4.5), Point(0, -8))
            Rigid(self)
        }
        love.w.position.y == panel.outline.center.y - 22 mm
        RightOf(heart, love, gap=6)
        AlignCenterY(heart, love)
        # the line "with love" + heart centred on the panel
        (love.bb.left + heart.bb.right) / 2 == panel.outline.center.x
    }

    solid bottom {
        panel = finger_panel(width=len_, height=out_w, thickness=t, finger=10 mm,
                             bottom="fingers", right="flat", top="fingers", left="flat")
    }

    front_wall = finger_panel(width=len_, height=out_h, thickness=t, finger=10 mm,
                              bottom="slots", right="flat", top="slots", left="flat")
    back_wall = finger_panel(width=len_, height=out_h, thickness=t, finger=10 mm,
                             bottom="slots", right="flat", top="slots", left="flat")

    # flat: top, bottom, then the two walls, in a column
    Below(bottom, top, gap=5)
    AlignLeft(bottom, top)
    Below(front_wall, bottom, gap=5)
    AlignLeft(front_wall, bottom)
    Below(back_wall, front_wall, gap=5)
    AlignLeft(back_wall, front_wall)

    # assembled: a tube along x, open at both ends
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, out_h - t), face="up")
    Place(front_wall, position=(0, -out_w / 2 + t, out_h / 2), face="front", up="up")
    Place(back_wall, position=(0, out_w / 2 - t, out_h / 2), face="back", up="up")

    assert top.panel.outline.width == 120 mm and top.panel.outline.height == 88 mm, "120 x 88"
    assert front_wall.outline.height == 20 mm, "20 tall outside"
    assert top.panel.outline.height - 2 * t >= 80 mm + 2 mm, "1 mm room each side of the bar"
    assert front_wall.outline.height - 2 * t >= 12 mm + 2 mm, "1 mm room over the bar"
    assert top.name.bb.width <= 100 mm, "name at most 100 wide"
    assert top.name.n.position.y - top.panel.outline.center.y == 10 mm, "name 10 above the middle"
    assert top.love.w.position.y - top.panel.outline.center.y == -22 mm, "second line 22 below"
    assert top.heart.bb.width <= 18 mm and top.heart.bb.width >= 16 mm, "heart about 17 wide"
    assert top.heart.bb.left - top.love.bb.right == 6 mm, "heart 6 from the words"
    assert top.name.bb.left >= top.panel.core.bb.left + 3 mm, "name clear of the ends"
    assert top.name.bb.top <= top.panel.core.bb.top - 3 mm, "name clear of the fingers"
    assert top.love.bb.bottom >= top.panel.core.bb.bottom + 3 mm, "line 2 clear of the fingers"
    assert distance(top.name, top.love) >= 4 mm, "the lines apart"
    assert distance(top.name, top.heart) >= 4 mm, "name clear of the heart"
}
