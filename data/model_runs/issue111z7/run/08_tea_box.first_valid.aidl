# Gifts: a tea gift box of 3 mm plywood. A finger-jointed open tray 160 x 160 x 60 mm
# outside (10 mm fingers) with 2 x 2 compartments (the std divider_tray), and a lift-off
# lid: a top plate 160 x 160 mm with R3 corners, a locating plate 153 x 153 mm glued under it
# (it drops inside the 154 mm opening), and a handle 50 x 20 mm with R8 top corners standing on
# two 10 mm tabs 3 mm deep (their centres 30 mm apart) glued into two 10 x 3.2 mm slots in
# the top plate, centred 45 mm above the lid's middle. On the lid: "TEA" in bold sans 28 mm
# tall engraved filled, its middle 5 mm below the lid's middle, and "for Grandma" in 6 mm
# strokes, its baseline 45 mm below the middle.

import "std/boxes.aidl"

thickness 3 mm

param size = 160 mm, min = 100 mm, max = 250 mm
param depth = 60 mm, min = 30 mm, max = 100 mm

t = 3 mm
slot_pitch = 30 mm

assembly tea_box {
    tray = divider_tray(length=size, width=size, height=depth, rows=2, cols=2, thickness=t,
                        finger=10 mm)

    solid lid {
        top = RoundedRectangle(center=(0, 0), width=size, height=size, corner_radius=3 mm)
        Fixed(top)
        hole slots {
            for x in [-slot_pitch / 2, slot_pitch / 2] {
                s = Rectangle(center=(x, 45 mm), width=10 mm, height=3.2 mm)
            }
        }
        drawing words {
            tea = Text("TEA", position=(0, -5 mm), size=28 mm, font="sans:Bold",
                       valign="middle", fill=true)
            who = Text("for Grandma", position=(0, -45 mm), size=6 mm)
        }
    }

    solid locator {
        plate = Rectangle(center=(0, 0), width=size - 2 * t - 1 mm, height=size - 2 * t - 1 mm)
    }

    solid handle {
        grip = RoundedRectangle(center=(0, 10 mm), width=50 mm, height=20 mm,
                                corner_radii=[8 mm, 8 mm, 0, 0])
        for x in [-slot_pitch / 2, slot_pitch / 2] {
            tab = Rectangle(center=(x, -1.5 mm), width=10 mm, height=t)
        }
    }

    RightOf(lid, tray, gap=10 mm)
    AlignTop(lid, tray)
    Below(locator, lid, gap=10 mm)
    AlignLeft(locator, lid)
    RightOf(handle, locator, gap=10 mm)
    AlignTop(handle, locator)

    assert tray.length == 160 mm and tray.width == 160 mm and tray.height == 60 mm, "160 x 160 x 60"
    assert lid.top.bb.width == 160 mm and lid.top.bb.height == 160 mm, "lid 160 x 160"
    assert locator.plate.bb.width == 153 mm, "locator 153"
    assert handle.grip.bb.width == 50 mm and handle.grip.bb.height == 20 mm, "handle 50 x 20"
    assert handle.tab[1].center.x - handle.tab[0].center.x == 30 mm, "tabs 30 apart"
    assert handle.tab[0].bb.width == 10 mm and handle.tab[0].bb.height == 3 mm, "tabs 10 x 3"
    assert lid.slots.s[0].bb.width == 10 mm and lid.slots.s[0].bb.height == 3.2 mm, "slots 10 x 3.2"
    assert lid.slots.s[0].center.y - lid.top.center.y == 45 mm, "slots 45 above the middle"
    assert lid.top.center.y - lid.words.tea.position.y == 5 mm, "TEA 5 below"
    assert lid.words.tea.size == 28 mm and lid.words.who.size == 6 mm, "28 and 6 mm"
}
