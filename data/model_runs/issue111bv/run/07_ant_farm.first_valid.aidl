# Request: a school ant farm (formicarium), a sandwich 200 mm wide and 150 mm tall: two 3 mm
# clear acrylic panes with a 6 mm birch-ply spacer frame between them (side and bottom bars
# 12 mm wide, open at the top), bolted through all three by four M3 bolts 6 mm in from each
# corner. A 6 mm ply top plug closes the opening: a 200 x 8 mm lip resting on top of the
# sandwich and a 12 mm tongue below it that fits between the side bars with 0.2 mm play each
# side. The back pane has two 8 mm feeding holes (for cotton plugs) 25 mm below the top,
# 60 mm and 140 mm from the left. The front pane is engraved "ANT FARM" (filled bold, 7 mm)
# centred over the bottom bar, and a millimetre scale up the left bar: a 3 mm tick every
# 10 mm from 20 to 130 mm up, 6 mm at each 50. The sandwich stands in two 6 mm ply feet
# (80 x 30 mm, 30 mm in from each end) each with a 12.2 mm wide, 15 mm deep notch from the top.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

W = 200 mm
H = 150 mm
BAR = 12 mm
PANE_T = 3 mm
PLY_T = 6 mm
STACK = 2 * PANE_T + PLY_T
PLAY = 0.2 mm
FOOT_L = 80 mm
FOOT_H = 30 mm
NOTCH = 15 mm

def pane(back=false) -> solid {
    thickness 3 mm
    glass = Rectangle(bottom_left=(0, 0), width=W, height=H)
    bolt = clearance_hole(size=3, cx=6 mm, cy=6 mm)
    bolts = CornerPattern(bolt, glass, inset=6 mm)
    if back {
        hole feed {
            a = Circle(center=(60, H - 25 mm), diameter=8 mm)
            b = Circle(center=(140, H - 25 mm), diameter=8 mm)
        }
    } else {
        drawing marks {
            title = Text("ANT FARM", position=(W / 2, BAR / 2), size=7, font="sans:Bold",
                         fill=true, valign="middle")
            for i in range(12) {
                tick = Line(start=(BAR - (6 mm if (20 + 10 * i) % 50 == 0 else 3 mm),
                                   20 mm + i * 10 mm),
                            end=(BAR, 20 mm + i * 10 mm))
            }
        }
    }
}

assembly ant_farm {
    front = pane()
    back = pane(back=true)

    solid frame {
        thickness 6 mm
        outline = Rectangle(bottom_left=(0, 0), width=W, height=H, construction=true)
        left = Rectangle(bottom_left=(0, 0), width=BAR, height=H)
        right = Rectangle(bottom_left=(W - BAR, 0), width=BAR, height=H)
        bottom = Rectangle(bottom_left=(0, 0), width=W, height=BAR)
        bolt = clearance_hole(size=3, cx=6 mm, cy=6 mm)
        bolts = CornerPattern(bolt, outline, inset=6 mm)
    }

    solid plug {
        thickness 6 mm
        lip = Rectangle(bottom_left=(0, H), width=W, height=8 mm)
        tongue = Rectangle(bottom_left=(BAR + PLAY, H - 12 mm), width=W - 2 * BAR - 2 * PLAY,
                           height=12 mm)
    }

    def foot() -> solid {
        thickness 6 mm
        body = Rectangle(bottom_left=(0, 0), width=FOOT_L, height=FOOT_H)
        notch = cross_halving(depth=NOTCH, thickness=STACK, clearance=PLAY, cx=FOOT_L / 2,
                              cy=FOOT_H)
    }
    foot_l = foot()
    foot_r = foot()

    # flat: panes side by side, frame and plug below, feet to the right
    RightOf(back, front, gap=6)
    AlignBottom(back, front)
    Below(frame, front, gap=6)
    AlignLeft(frame, front)
    RightOf(plug, frame, gap=6)
    AlignBottom(plug, frame)
    Below(foot_l, plug, gap=6)
    AlignLeft(foot_l, plug)
    RightOf(foot_r, foot_l, gap=6)
    AlignBottom(foot_r, foot_l)

    # assembled: the sandwich upright along x (front pane at y -3..0), standing in the feet
    Place(front, position=(0, 0, NOTCH), rotation=(90 deg, 0, 0))
    Place(frame, position=(0, PLY_T, NOTCH), rotation=(90 deg, 0, 0))
    Place(plug, position=(0, PLY_T, NOTCH), rotation=(90 deg, 0, 0))
    Place(back, position=(0, PLY_T + PANE_T, NOTCH), rotation=(90 deg, 0, 0))
    Place(foot_l, position=(30 mm - PLY_T / 2, STACK / 2 - PANE_T - FOOT_L / 2, 0),
          rotation=(90 deg, 0, 90 deg))
    Place(foot_r, position=(W - 30 mm - PLY_T / 2, STACK / 2 - PANE_T - FOOT_L / 2, 0),
          rotation=(90 deg, 0, 90 deg))

    assert front.glass.bb.width == 200 mm and front.glass.bb.height == 150 mm, "200 x 150"
    assert frame.left.bb.width == 12 mm and frame.bottom.bb.height == 12 mm, "12 mm bars"
    # play: the tongue 0.2 mm narrower each side than the opening between the bars (each part
    # read in its own frame, as the sheet layout moves them apart)
    assert (frame.right.bb.left - frame.left.bb.right) - plug.tongue.bb.width == 2 * 0.2 mm,
        "0.2 mm play each side"
    assert plug.tongue.bb.left - plug.lip.bb.left == 12 mm + 0.2 mm, "tongue centred"
    assert plug.lip.bb.height == 8 mm and plug.tongue.bb.height == 12 mm, "8 mm lip, 12 mm tongue"
    assert back.feed.a.center.x - back.glass.bb.left == 60 mm, "feed hole at 60 mm"
    assert back.feed.b.center.x - back.glass.bb.left == 140 mm, "feed hole at 140 mm"
    assert back.glass.bb.top - back.feed.a.center.y == 25 mm, "feed holes 25 mm below the top"
    assert back.glass.bb.top - back.feed.a.bb.top > plug.lip.bb.bottom - plug.tongue.bb.bottom,
        "feed holes below the plug"
    assert len(front.marks.tick) == 12, "ticks 20..130"
    assert foot_l.notch.cut.bb.width == 12.2 mm, "12.2 mm notch"
    assert foot_l.notch.cut.bb.height == 15 mm, "15 mm deep"
}
