# Request (parties): a carry caddy for six 9 oz party cups (78 mm rim, 70 mm across 32 mm
# below the rim, 95 mm tall), 2 rows of 3, in 4 mm ply, to carry drinks out to the garden.
# A top plate 274 x 188 with six 70 mm holes (88 mm apart along, 90 mm across) holds the
# cups; a floor plate of the same size 10 mm off the ground catches drips; both have two
# 40 mm tabs at each end through two end panels. Each end panel is 188 wide x 110 tall with
# a 50 mm wide upright in the middle rising to 200 mm with a round top; a handle board
# 70 mm tall (z 120 to 190) runs between the uprights on a 40 mm tenon at each end, with a
# 110 x 28 finger slot, its top 20 mm below the handle's top. "CHEERS" and "PROST" are
# engraved (filled, bold, 14 mm) on the handle either side of the slot. Slots 0.15 mm over.

units mm
t = 4 mm
thickness t

inner_l = 274 mm           # between the end panels
width = 188 mm
hole_d = 70 mm
pitch_x = 88 mm
pitch_y = 90 mm
floor_z = 10 mm
top_z = floor_z + t + 65 mm      # top plate's underside
end_h = 110 mm
up_w = 50 mm
up_top = 200 mm
handle_lo = 120 mm
handle_hi = 190 mm
fit = 0.15 mm
grip_cz = handle_hi - 20 mm - 14 mm

import "std/joints.aidl"

def plate(holes=false) -> solid {
    # the tabs' tips reach through the end panels: x = +-(inner_l / 2 + t)
    body = Rectangle(center=(0, 0), width=inner_l + 2 * t, height=width)
    r_end = tab_and_slot(part="tab", length=width, thickness=t, tabs=2, tab=40 mm, screw=0,
                         rotation=-90 deg, cx=inner_l / 2 + t, cy=0)
    l_end = tab_and_slot(part="tab", length=width, thickness=t, tabs=2, tab=40 mm, screw=0,
                         rotation=90 deg, cx=-inner_l / 2 - t, cy=0)
    if holes {
        hole cups {
            for i in range(3) {
                for j in range(2) {
                    c = Circle(center=((i - 1) * pitch_x, (j - 0.5) * pitch_y), diameter=hole_d)
                }
            }
        }
    }
}

def end_panel() -> solid {
    low = Rectangle(bottom_left=(-width / 2, 0), width=width, height=end_h)
    post = Rectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=up_top - up_w / 2)
    cap = Circle(center=(0, up_top - up_w / 2), diameter=up_w)
    floor_s = tab_and_slot(part="slot", length=width, thickness=t, tabs=2, tab=40 mm, screw=0,
                           clearance=fit, cx=0, cy=floor_z + t / 2)
    top_s = tab_and_slot(part="slot", length=width, thickness=t, tabs=2, tab=40 mm, screw=0,
                         clearance=fit, cx=0, cy=top_z + t / 2)
    handle_s = tab_and_slot(part="slot", length=handle_hi - handle_lo, thickness=t, tabs=1,
                            tab=40 mm, screw=0, clearance=fit, rotation=90 deg, cx=0,
                            cy=(handle_lo + handle_hi) / 2)
}

assembly cup_caddy {
    floor = plate(holes=false)
    top = plate(holes=true)
    end_r = end_panel()
    end_l = end_panel()
    solid handle {
        board = Rectangle(bottom_left=(-inner_l / 2 - t, handle_lo), width=inner_l + 2 * t,
                          height=handle_hi - handle_lo)
        r_ten = tab_and_slot(part="tab", length=handle_hi - handle_lo, thickness=t, tabs=1,
                             tab=40 mm, screw=0, rotation=-90 deg, cx=inner_l / 2 + t,
                             cy=(handle_lo + handle_hi) / 2)
        l_ten = tab_and_slot(part="tab", length=handle_hi - handle_lo, thickness=t, tabs=1,
                             tab=40 mm, screw=0, rotation=90 deg, cx=-inner_l / 2 - t,
                             cy=(handle_lo + handle_hi) / 2)
        hole grip {
            s = Slot(center=(0, grip_cz), length=110, width=28)
        }
        drawing words {
            a = Text("CHEERS", position=(-96 mm, grip_cz), size=14, font="sans:Bold",
                     valign="middle", fill=true, max_width=70)
            b = Text("PROST", position=(96 mm, grip_cz), size=14, font="sans:Bold",
                     valign="middle", fill=true, max_width=70)
        }
    }

    # flat on the sheet
    RightOf(top, floor, gap=8)
    AlignTop(top, floor)
    Below(handle, floor, gap=8)
    AlignLeft(handle, floor)
    RightOf(end_r, handle, gap=8)
    AlignTop(end_r, handle)
    RightOf(end_l, end_r, gap=8)
    AlignTop(end_l, end_r)

    # assembled
    Place(floor, position=(0, 0, floor_z), face="up")
    Place(top, position=(0, 0, top_z), face="up")
    Place(end_r, position=(inner_l / 2, 0, 0), face="right", up="up")
    Place(end_l, position=(-inner_l / 2, 0, 0), face="left", up="up")
    Place(handle, position=(0, t / 2, 0), face="front", up="up")

    assert len(top.cups.c) * len(top.cups.c[0]) == 6, "six cups"
    assert top.cups.c[0][0].diameter == 70 mm, "70 mm holes"
    assert top.cups.c[1][0].center.x - top.cups.c[0][0].center.x == 88 mm and
        top.cups.c[0][1].center.y - top.cups.c[0][0].center.y == 90 mm, "88 along, 90 across"
    assert top.body.height == 188 mm and top.body.width - 2 * t == 274 mm, "plates 274 x 188"
    assert top_z - (floor_z + t) == 65 mm, "cups hang 63 mm below the top plate: floor clear"
    assert handle_lo - (top_z + t + 32 mm) >= 5 mm, "handle clear of the cup rims"
    assert end_r.post.bb.height + end_r.cap.bb.height / 2 == 200 mm, "uprights 200 tall"
    assert distance(handle.words.a, handle.grip.s) >= 5 mm and
        distance(handle.words.b, handle.grip.s) >= 5 mm, "words clear of the finger slot"
    assert handle.words.a.bb.left >= handle.board.bb.left + t + 3 mm and
        handle.words.b.bb.right <= handle.board.bb.right - t - 3 mm, "words clear of the tenons"
}
