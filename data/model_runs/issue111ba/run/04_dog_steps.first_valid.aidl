# Request (pets): three steps for our old dachshund Biscuit to get onto the sofa, from 9 mm
# ply. Three steps, each 120 mm rise and 200 mm run, so 360 mm high and 600 mm deep; 400 mm
# wide over the side panels. Two stepped side panels; three treads whose ends carry two
# 40 mm glued tenons each, through mortises in the sides, the tread tops flush with the
# step edges. Each side has a dog-bone cut-out (240 mm long, 74 mm tall: a 30 mm shaft and
# 20 mm radius knuckles) low down to save weight, at least 40 mm of wood all round it. The
# right side (the one facing the room) has "BISCUIT" engraved filled in 20 mm bold letters
# on its tall part, and every tread has an engraved paw print in its middle.

units mm
thickness 9 mm
kerf 0.2 mm

import "std/joints.aidl"

ply = 9 mm
rise = 120 mm
run = 200 mm
steps = 3
width = 400 mm
tenon = 40 mm
bone_len = 240 mm
shaft_h = 30 mm
knuckle_r = 20 mm
knuckle_dy = 17 mm       # knuckle centres above and below the shaft's axis: 74 mm overall
bone_x = 400 mm
bone_y = 110 mm

def side_panel() -> solid {
    profile = Polygon([(0, 0), (run * 3, 0), (run * 3, rise * 3), (run * 2, rise * 3),
                       (run * 2, rise * 2), (run, rise * 2), (run, rise), (0, rise)])
    Fixed(profile)
    hole bone {
        shaft = Rectangle(center=(bone_x, bone_y), width=bone_len - 2 * knuckle_r,
                          height=shaft_h)
        k1 = Circle(center=(bone_x - bone_len / 2 + knuckle_r, bone_y + knuckle_dy), radius=knuckle_r)
        k2 = Circle(center=(bone_x - bone_len / 2 + knuckle_r, bone_y - knuckle_dy), radius=knuckle_r)
        k3 = Circle(center=(bone_x + bone_len / 2 - knuckle_r, bone_y + knuckle_dy), radius=knuckle_r)
        k4 = Circle(center=(bone_x + bone_len / 2 - knuckle_r, bone_y - knuckle_dy), radius=knuckle_r)
    }
    for i in range(steps) {
        m = tab_and_slot(part="slot", length=run, thickness=ply, tabs=2, tab=tenon, screw=0,
                         clearance=0.1 mm, cx=run * i + run / 2, cy=rise * (i + 1) - ply / 2)
    }
}

def tread() -> solid {
    board = Rectangle(center=(0, 0), width=width, height=run)
    Fixed(board)
    left = tab_and_slot(part="tab", length=run, thickness=ply, tabs=2, tab=tenon, screw=0,
                        rotation=90 deg, cx=-width / 2, cy=0 mm)
    right = tab_and_slot(part="tab", length=run, thickness=ply, tabs=2, tab=tenon, screw=0,
                         rotation=-90 deg, cx=width / 2, cy=0 mm)
    drawing paw {
        pad = Ellipse(center=(0, -8), rx=16, ry=12, fill=true)
        t1 = Ellipse(center=(-17, 8), rx=5, ry=7, rotation=20 deg, fill=true)
        t2 = Ellipse(center=(-6, 16), rx=5, ry=7, rotation=5 deg, fill=true)
        t3 = Ellipse(center=(6, 16), rx=5, ry=7, rotation=-5 deg, fill=true)
        t4 = Ellipse(center=(17, 8), rx=5, ry=7, rotation=-20 deg, fill=true)
    }
    CenterInside(paw, board)
}

assembly dog_steps {
    side_l = side_panel()
    side_r = side_panel()
    tread_1 = tread()
    tread_2 = tread()
    tread_3 = tread()

    drawing name {
        t = Text("BISCUIT", position=(0, 0), size=20, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CutInto(name, side_r)
    AlignCenterX(name, side_r.profile.edges[2])
    name.t.position.y == side_r.profile.bb.bottom + 300 mm
    name.t.position.x == side_r.profile.bb.left + 500 mm

    # flat on the sheet
    RightOf(side_r, side_l, gap=10)
    AlignBottom(side_r, side_l)
    Below(tread_1, side_l, gap=10)
    RightOf(tread_2, tread_1, gap=10)
    RightOf(tread_3, tread_2, gap=10)
    AlignTop(tread_2, tread_1)
    AlignTop(tread_3, tread_1)

    # assembled: x across, y front to back, z up; sides stood on edge, treads on the steps
    Place(side_l, rotation=(90 deg, 0, 90 deg), position=(-width / 2, 0, 0))
    Place(side_r, rotation=(90 deg, 0, 90 deg), position=(width / 2 - ply, 0, 0))
    Place(tread_1, position=(0, run / 2, rise - ply))
    Place(tread_2, position=(0, run * 1.5, rise * 2 - ply))
    Place(tread_3, position=(0, run * 2.5, rise * 3 - ply))

    assert side_l.profile.bb.height == 360 mm and side_l.profile.bb.width == 600 mm, "360 high, 600 deep"
    assert tread_1.board.width == 400 mm, "400 wide over the sides"
    assert tread_1.bb.width == 400 mm, "tenon tips flush with the sides' outer faces"
    assert len(side_l.m) == 3, "three treads"
    assert side_l.bone.bb.width == 240 mm and side_l.bone.bb.height == 74 mm, "bone 240 x 74"
    assert side_l.bone.bb.bottom - side_l.profile.bb.bottom >= 40 mm, "40 mm under the bone"
    assert side_l.bone.bb.left - (side_l.profile.bb.left + run) >= 40 mm, "40 mm before the bone"
    assert side_l.profile.bb.right - side_l.bone.bb.right >= 40 mm, "40 mm behind the bone"
    assert (side_l.profile.bb.bottom + rise * 2) - side_l.bone.bb.top >= 40 mm, "40 mm above the bone"
    assert side_l.bone.bb.top < side_l.profile.bb.bottom + rise - ply or side_l.bone.bb.left > side_l.profile.bb.left + run, "bone clear of tread 1"
}
