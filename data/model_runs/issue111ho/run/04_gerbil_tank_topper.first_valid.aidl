# Request (pets): a topper that sits on a 600 x 300 mm glass gerbil tank and adds 250 mm
# of height, cut from 6 mm ply as a finger-jointed box 600 x 300 x 250 mm outside. Its
# bottom is only a frame, 20 mm wide all round (a 560 x 260 opening), so the gerbils climb
# up from the tank. Mesh is stapled behind windows: two 240 x 160 mm windows in the front
# and in the back, 30 mm above the bottom edge and 20 mm apart; one 200 x 160 mm window
# in each end (200 along the tank, 160 up), centred; a 500 x 200 mm window in the lid,
# centred. "PIP & SQUEAK" engraved filled in 20 mm bold letters on the front, centred
# between the windows' tops and the top edge.

units mm
thickness 6 mm

import "std/joints.aidl"

assembly topper {
    box = finger_box(length=600 mm, depth=300 mm, height=250 mm, thickness=6 mm,
                     finger=20 mm, closed=true, gap=10 mm, outside=true)

    # the open bottom: a frame 20 mm wide
    hole floor_opening {
        r = Rectangle(center=(0, 0), width=560, height=260)
    }
    CenterInside(floor_opening, box.bottom)
    CutInto(floor_opening, box.bottom)

    # two mesh windows in the front and the back, 30 mm above the bottom edge
    hole front_windows {
        a = Rectangle(center=(-130, 0), width=240, height=160)
        b = Rectangle(center=(130, 0), width=240, height=160)
    }
    AlignCenterX(front_windows, box.front)
    front_windows.bb.bottom == box.front.bb.bottom + 30 mm
    CutInto(front_windows, box.front)

    hole back_windows {
        a = Rectangle(center=(-130, 0), width=240, height=160)
        b = Rectangle(center=(130, 0), width=240, height=160)
    }
    AlignCenterX(back_windows, box.back)
    back_windows.bb.bottom == box.back.bb.bottom + 30 mm
    CutInto(back_windows, box.back)

    # the ends lie on their side in the net: 250 (height) in x, 300 (depth) in y
    hole left_window {
        r = Rectangle(center=(0, 0), width=160, height=200)
    }
    CenterInside(left_window, box.left)
    CutInto(left_window, box.left)
    hole right_window {
        r = Rectangle(center=(0, 0), width=160, height=200)
    }
    CenterInside(right_window, box.right)
    CutInto(right_window, box.right)

    hole lid_window {
        r = Rectangle(center=(0, 0), width=500, height=200)
    }
    CenterInside(lid_window, box.lid)
    CutInto(lid_window, box.lid)

    drawing names {
        t = Text("PIP & SQUEAK", (0, 0), size=20, font="sans:Bold", fill=true,
                 valign="middle")
    }
    AlignCenterX(names, box.front)
    names.bb.center_y == (front_windows.bb.top + box.front.bb.top) / 2
    CutInto(names, box.front)

    assert box.front.bb.width == 600 mm and box.front.bb.height == 250 mm, "600 long, 250 tall"
    assert box.bottom.bb.width - floor_opening.bb.width == 2 * 20 mm, "20 mm frame along"
    assert box.bottom.bb.height - floor_opening.bb.height == 2 * 20 mm, "20 mm frame across"
    assert front_windows.b.bb.left - front_windows.a.bb.right == 20 mm, "windows 20 mm apart"
    assert front_windows.bb.bottom - box.front.bb.bottom == 30 mm, "windows 30 mm up"
    assert left_window.r.bb.height == 200 mm and left_window.r.bb.width == 160 mm, "end window"
    assert distance(names, front_windows) >= 5 mm, "names clear of the windows"
    assert box.front.bb.top - names.bb.top >= 5 mm, "names clear of the top fingers"
}
