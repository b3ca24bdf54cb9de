# Request (crafts): a card-making scoring board, 6 mm MDF. A 320 x 320 mm base with 6 mm
# rounded corners; along its left edge a fence 300 mm long standing 25 mm above the base,
# glued into three mortises by three 30 mm tabs, the card butting against its face. Score
# grooves engraved every 10 mm from the fence's face, 29 of them, running from 30 mm above
# the bottom edge to 5 mm below the top; under each groove its number of centimetres from the
# fence, 4 mm high. A thumb notch (r15) bitten out of the middle of the right edge to lift the
# card. A scoring stylus cut from the same sheet: 150 mm long, a 6 mm round tip tapering to a
# 20 mm round butt with a 6 mm hanging hole.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
S = 320 mm         # the base's side
pitch = 10 mm
grooves = 29
fence_h = 25 mm    # above the base
face_x = -S / 2 + T   # the fence's working face on the base

assembly scoring_board {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=S, height=S, corner_radius=6)
        mortise = tab_and_slot(part="slot", length=300 mm, thickness=T, tabs=3, tab=30 mm,
                               screw=0, rotation=90 deg, cx=-S / 2 + T / 2, cy=0 mm)
        hole notch { c = Circle(center=(S / 2, 0), radius=15) }
        drawing score {
            for k in range(1, grooves + 1) {
                g = Line((face_x + k * pitch, -S / 2 + 30 mm), (face_x + k * pitch, S / 2 - 5 mm))
                n = Text(str(k), position=(face_x + k * pitch, -S / 2 + 24 mm), size=4,
                         valign="top")
            }
        }
    }

    solid fence {
        # the tabs' tips on y = -(fence_h + T) / 2, through the base; the base's top at +T above
        body = Rectangle(center=(0, 0), width=300, height=fence_h + T)
        tabs = tab_and_slot(part="tab", length=300 mm, thickness=T, tabs=3, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-(fence_h + T) / 2)
    }

    solid stylus {
        shape = Hull(Circle(center=(0, 0), radius=3), Circle(center=(140, 0), radius=10))
        hole hang { c = Circle(center=(140, 0), diameter=6) }
    }

    RightOf(fence, base, gap=10)
    AlignTop(fence, base)
    RightOf(stylus, base, gap=10)
    Below(stylus, fence, gap=10)

    # 3D: the base flat; the fence standing on its left edge (its x along the base's y, its y
    # up, its thickness along x); the stylus lying on the base
    Place(fence, rotation=(90 deg, 0, 90 deg), position=(-S / 2, 0, (fence_h + T) / 2))
    Place(stylus, position=(-60, -100, T))

    assert base.body.bb.width == 320 mm and base.body.bb.height == 320 mm, "320 x 320 base"
    assert len(base.score.g) == 29, "29 grooves"
    assert base.score.g[1].start.x - base.score.g[0].start.x == 10 mm, "grooves 10 apart"
    assert base.score.g[0].start.x - (base.body.bb.left + T) == 10 mm, "first groove 1 cm out"
    assert base.score.g[0].start.y - base.body.bb.bottom == 30 mm, "grooves from 30 up"
    assert base.body.bb.top - base.score.g[0].end.y == 5 mm, "to 5 below the top"
    assert fence.body.bb.height - T == 25 mm, "fence 25 above the base"
    assert fence.body.bb.width == 300 mm, "fence 300 long"
    assert stylus.shape.bb.width == 150 mm, "stylus 150 long"
    assert stylus.shape.bb.height == 20 mm, "20 mm butt"
}
