# Request (electronics): a DIN-rail mount for a small relay module (mounting holes 58 x 40 mm,
# M3). A 3 mm acrylic carrier plate 90 x 70 mm, corners R4, four 3.2 mm holes on the
# 58 x 40 rectangle centred on the plate, engraved "DIN 35" and "RELAY"; it is glued onto two
# clips cut from 6 mm acrylic, standing across the rail 24 mm either side of the plate's
# centre, each in two mortise slots (8 mm tabs, 3 mm long, slot clearance 0.2 mm). Each clip
# is the profile of a 35 mm top-hat rail mount (rail EN 60715: 35 wide, flanges 1 mm thick):
# a body 25 deep from the rail's front face, a fixed top hook whose lip reaches 3 mm behind
# the upper flange (0.2 mm clearance at the flange's edge and behind it, lip 4 mm from the
# rail face), and at the bottom the same hook on a spring beam 3 mm thick that flexes down,
# separated from the body by a 1.5 mm slit 21 mm long, with a pull tab (4 mm screwdriver
# hole) below it. Rail grip: 35.4 mm between the two hooks.

import "std/joints.aidl"

thickness 6 mm
clip_t = 6 mm
plate_t = 3 mm
rail_w = 35 mm
flange = 1 mm
clr = 0.2 mm
lip_reach = 3 mm
edge_len = 49 mm      # the clip's glued edge, y -24 to 25

def clip() -> solid {
    # rail's front face on x = 0, the rail centred on y = 0; the plate edge at x = 25
    body = Rectangle(bottom_left=(0, -19.5), width=25, height=44.5)
    # fixed top hook
    hook_top = Rectangle(bottom_left=(-4, rail_w / 2 + clr), width=4, height=3.3)
    lip_top = Rectangle(bottom_left=(-4, rail_w / 2 + clr - lip_reach - clr),
                        width=4 - flange - clr, height=lip_reach + clr)
    # spring beam with the bottom hook; root at x 21..25
    root = Rectangle(bottom_left=(21, -24), width=4, height=4.5)
    beam = Rectangle(bottom_left=(-4, -24), width=29, height=3)
    riser = Rectangle(bottom_left=(-4, -21), width=3.5, height=21 - rail_w / 2 - clr)
    lip_bot = Rectangle(bottom_left=(-4, -(rail_w / 2 + clr)), width=4 - flange - clr,
                        height=lip_reach + clr)
    pull = RoundedRectangle(bottom_left=(0, -31), width=10, height=8, corner_radius=3)
    hole pull_hole {
        c = Circle(center=(5, -27.5), diameter=4)
    }
    # tabs on the plate edge (x = 25), the clip toward -x
    tabs = tab_and_slot(part="tab", length=edge_len, thickness=plate_t, tabs=2, tab=8 mm,
                        screw=0, rotation=-90 deg, cx=25 mm, cy=0.5 mm)
    assert hook_top.bb.bottom - riser.bb.top == 35.4 mm, "35.4 mm between the hooks"
    assert body.bb.left - lip_top.bb.right == flange + clr, "flange room behind the rail face"
    assert beam.bb.height == 3 mm, "spring beam 3 mm"
    assert body.bb.bottom - beam.bb.top == 1.5 mm, "1.5 mm slit"
    assert root.bb.left - body.bb.left == 21 mm, "slit 21 mm long"
}

assembly din_mount {
    solid plate {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=90, height=70, corner_radius=4)
        hole board {
            for i in range(4) {
                c = Circle(center=((i % 2 - 0.5) * 58, (i // 2 - 0.5) * 40), diameter=3.2)
            }
        }
        slots_l = tab_and_slot(part="slot", length=edge_len, thickness=clip_t, tabs=2, tab=8 mm,
                               screw=0, clearance=0.2 mm, rotation=90 deg, cx=-24 mm, cy=0.5 mm)
        slots_r = tab_and_slot(part="slot", length=edge_len, thickness=clip_t, tabs=2, tab=8 mm,
                               screw=0, clearance=0.2 mm, rotation=90 deg, cx=24 mm, cy=0.5 mm)
        drawing label {
            din = Text("DIN 35", position=(0, 27), size=5, valign="middle")
            name = Text("RELAY", position=(0, -27), size=5, valign="middle")
        }
        assert body.bb.width == 90 mm and body.bb.height == 70 mm, "plate 90 x 70"
        assert board.c[1].center.x - board.c[0].center.x == 58 mm, "holes 58 apart"
        assert board.c[2].center.y - board.c[0].center.y == 40 mm, "holes 40 apart"
    }
    clip_a = clip()
    clip_b = clip()
    RightOf(clip_a, plate, gap=8)
    AlignTop(clip_a, plate)
    RightOf(clip_b, clip_a, gap=8)
    AlignTop(clip_b, clip_a)
    assert len(plate.board.c) == 4, "four board holes"
}
