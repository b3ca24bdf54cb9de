# REQUEST (01, home): an over-door coat-hook rail for a wardrobe door 40 mm thick that
# closes with 8 mm to spare above it. 6 mm birch ply. Two hangers (side profiles) ride
# over the door: a 42 mm gap (door + 2 mm), a 6 mm bridge over the door top, 12 mm wide
# legs, a back leg 40 mm down the back of the door and a front leg 220 mm down the front.
# A rail 400 x 70 mm with R8 corners hangs on the front legs by two glued 10 mm tabs each
# (through mortises), its top 140 mm below the door top. Four J hooks 100 mm apart
# (12 mm strip, 60 mm stem, a J 40 mm across on its centre line with a 20 mm tip),
# each glued into the rail by one 30 mm tenon. "HARTLEY" engraved filled (serif)
# between the two middle hooks.

import "std/joints.aidl"

thickness 6 mm

door = 40 mm
gap = door + 2 mm
strip = 12 mm
bridge = 6 mm
back_leg = 40 mm
front_leg = 220 mm
rail_w = 400 mm
rail_h = 70 mm
rail_drop = 140 mm
hook_pitch = 100 mm
hanger_x = 100 mm      # each hanger's middle plane from the rail's centre
ply = 6 mm
rail_mid = -rail_drop - rail_h / 2
stem_bottom = -205 mm

def hanger() -> solid {
    # side profile: the door's top at y = 0, the gap from x = 0 (back) to x = gap (front)
    top = Rectangle(bottom_left=(-strip, 0), width=gap + 2 * strip, height=bridge)
    back = Rectangle(bottom_left=(-strip, -back_leg), width=strip, height=back_leg)
    front = Rectangle(bottom_left=(gap, -front_leg), width=strip, height=front_leg)
    # a strip over the rail's height, cut down to two 10 mm tabs
    lug = Rectangle(bottom_left=(gap + strip, -rail_drop - rail_h), width=ply, height=rail_h)
    joint = tab_and_slot(part="tab", length=rail_h, thickness=ply, tabs=2, tab=10 mm, screw=0,
                         rotation=-90 deg, cx=gap + strip + ply, cy=rail_mid)
    Rigid(self)
}

def hook() -> solid {
    # side profile: back edge at x = 0 on the rail's face, y as on the door
    stem = Rectangle(bottom_left=(0, stem_bottom), width=strip, height=60 mm)
    bend = ArcSlot(center=(strip / 2 + 20 mm, stem_bottom), radius=20 mm, start_angle=180 deg,
                   end_angle=360 deg, width=strip)
    tip = Slot(start=(strip / 2 + 40 mm, stem_bottom), end=(strip / 2 + 40 mm, stem_bottom + 20 mm),
               width=strip)
    lug = Rectangle(bottom_left=(-ply, rail_mid - 20 mm), width=ply, height=40 mm)
    tenon = tab_and_slot(part="tab", length=40 mm, thickness=ply, tabs=1, tab=30 mm, screw=0,
                         rotation=90 deg, cx=-ply, cy=rail_mid)
    Rigid(self)
}

assembly door_hook {
    left_hanger = hanger()
    right_hanger = hanger()

    solid rail {
        board = RoundedRectangle(center=(0, rail_mid), width=rail_w, height=rail_h, corner_radius=8)
        for i in range(2) {
            hang = tab_and_slot(part="slot", length=rail_h, thickness=ply, tabs=2, tab=10 mm,
                                screw=0, rotation=90 deg, cx=(2 * i - 1) * hanger_x, cy=rail_mid)
        }
        for i in range(4) {
            peg = tab_and_slot(part="slot", length=40 mm, thickness=ply, tabs=1, tab=30 mm,
                               screw=0, rotation=90 deg, cx=(i - 1.5) * hook_pitch, cy=rail_mid)
        }
        drawing name {
            t = Text("HARTLEY", position=(0, rail_mid), size=14, font="serif", valign="middle",
                     fill=true, max_width=70 mm)
        }
        assert board.bb.width == 400 mm and board.bb.height == 70 mm, "rail 400 x 70"
        assert peg[1].slot[0].bb.center_x - peg[0].slot[0].bb.center_x == 100 mm, "hooks 100 apart"
        assert hang[1].slot[0].bb.center_x - hang[0].slot[0].bb.center_x == 200 mm, "hangers 200 apart"
        assert distance(name.t, peg[1]) >= 4 mm and distance(name.t, peg[2]) >= 4 mm,
            "name clear of the middle hooks"
    }

    for i in range(4) {
        hooks = hook()
        # 3D: the hook's back edge on the rail's front face (y = -19), standing out to the front
        Place(hooks, position=((i - 1.5) * hook_pitch + ply / 2, -19, 0), face="left", up="up")
    }

    # 3D: the door from y = 0 (front) to y = 40; its top at z = 0
    Place(left_hanger, position=(-hanger_x + ply / 2, 41, 0), face="left", up="up")
    Place(right_hanger, position=(hanger_x + ply / 2, 41, 0), face="left", up="up")
    Place(rail, position=(0, -13, 0), face="front", up="up")

    # flat on the sheet
    RightOf(right_hanger, left_hanger, gap=8)
    AlignTop(right_hanger, left_hanger)
    RightOf(hooks[0], right_hanger, gap=8)
    AlignTop(hooks[0], right_hanger)
    for i in range(1, 4) {
        RightOf(hooks[i], hooks[i - 1], gap=8)
        AlignTop(hooks[i], hooks[i - 1])
    }
    Below(rail, left_hanger, gap=8)
    AlignLeft(rail, left_hanger)

    assert len(hooks) == 4, "four hooks"
    assert left_hanger.front.bb.left - left_hanger.back.bb.right == 42 mm, "door + 2 mm"
    assert left_hanger.top.bb.height == 6 mm, "bridge 6 mm"
    assert left_hanger.top.bb.bottom - left_hanger.back.bb.bottom == 40 mm, "back leg 40"
    assert left_hanger.top.bb.bottom - left_hanger.front.bb.bottom == 220 mm, "front leg 220"
    assert left_hanger.top.bb.bottom - left_hanger.lug.bb.top == 140 mm, "rail top 140 below"
    assert hooks[0].stem.bb.height == 60 mm, "stem 60"
    assert hooks[0].tip.bb.center_x - hooks[0].stem.bb.center_x == 40 mm, "J 40 across"
}
