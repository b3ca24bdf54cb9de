# Request (signs): a wall directory for a corridor, 300 x 380 mm, R10 corners, with five
# slide-in name slats that can be changed, layered acrylic.
# - Back plate (3 mm, dark grey): four M4 screw holes 12 mm in from each side at the
#   corners.
# - Spacer (4 mm ply): the same outline and screw holes; five channels 40 mm tall,
#   their centres at y = 70, 20, -30, -80, -130 from the sign's centre, from 135 mm left
#   of the centre out through the right edge (the slats slide in from the right); a
#   260 x 60 mm window behind the header, centred 145 mm above the centre.
# - Front plate (3 mm, white): the same screw holes, countersunk for M4 flat heads (8 mm);
#   five windows 260 x 30 mm from 125 mm left of the centre, centred on the channels;
#   "LEVEL 2" cut through in 40 mm bold stencil letters, centred 145 mm above the centre,
#   so the dark back shows through.
# - Five slats (3 mm white): 294 x 39.4 mm (0.3 mm play in the 40 mm channel), from 134 mm
#   left of the centre to 10 mm past the right edge, that end rounded R10; the name
#   engraved filled, 12 mm bold, starting 8 mm inside the window's left end:
#   101 RECEPTION, 102 DR A. PATEL, 103 M. OKONKWO, 104 MEETING ROOM, 105 KITCHEN.

import "std/fasteners.aidl"

thickness 3 mm

W = 300 mm
H = 380 mm
ch_h = 40 mm
ch_left = -135 mm
win_w = 260 mm
win_h = 30 mm
win_left = -125 mm
rows = [70, 20, -30, -80, -130]
names = ["101  RECEPTION", "102  DR A. PATEL", "103  M. OKONKWO", "104  MEETING ROOM",
         "105  KITCHEN"]
slat_h = ch_h - 0.6 mm
slat_left = -134 mm
slat_l = W / 2 + 10 mm - slat_left
header_y = 145 mm
spacer_t = 4 mm

def screws() -> hole {
    for p in [[-1, -1], [1, -1], [-1, 1], [1, 1]] {
        s = Circle(center=(p[0] * (W / 2 - 12), p[1] * (H / 2 - 12)), diameter=4.5)
    }
}

def slat(label="") -> solid {
    # drawn in the sign's x, centred on y = 0
    bar = RoundedRectangle(bottom_left=(slat_left, -slat_h / 2), width=slat_l, height=slat_h,
                           corner_radii=[0, 10, 10, 0])
    drawing name {
        t = Text(label, position=(win_left + 8 mm, 0), size=12, anchor="start", valign="middle",
                 font="sans:Bold", fill=true)
    }
    Fixed(bar)
    Fixed(name)
}

assembly directory {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
        holes = screws()
        Fixed(plate)
        Fixed(holes)
    }
    Place(back, position=(0, 0, 0), face="up")

    solid spacer {
        thickness 4 mm
        plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
        holes = screws()
        for y in rows {
            hole channel { r = Rectangle(bottom_left=(ch_left, y - ch_h / 2), width=W / 2 - ch_left + 5 mm,
                                         height=ch_h) }
        }
        hole header_window { r = Rectangle(center=(0, header_y), width=260, height=60) }
        Fixed(plate)
        Fixed(holes)
    }
    Place(spacer, position=(0, 0, 3), face="up")

    solid front {
        plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
        holes = screws()
        Countersink(holes, diameter=8)
        for y in rows {
            hole window { r = Rectangle(bottom_left=(win_left, y - win_h / 2), width=win_w, height=win_h) }
        }
        hole header {
            t = Text("LEVEL 2", position=(0, header_y), size=40, font="sans:Bold", stencil=true,
                     valign="middle")
        }
        Fixed(plate)
        Fixed(holes)
    }
    Place(front, position=(0, 0, 3 + spacer_t), face="up")

    for i in range(5) {
        s = slat(label=names[i])
        Place(s, position=(0, rows[i], 3.5), face="up")
    }

    # flat layout
    RightOf(spacer, back, gap=10)
    AlignTop(spacer, back)
    RightOf(front, spacer, gap=10)
    AlignTop(front, spacer)
    Below(s[0], back, gap=10)
    AlignLeft(s[0], back)
    for i in range(1, 5) {
        Below(s[i], s[i - 1], gap=5)
        AlignLeft(s[i], s[i - 1])
    }

    assert back.plate.bb.width == 300 mm and back.plate.bb.height == 380 mm, "300 x 380"
    assert len(s) == 5 and len(front.window) == 5 and len(spacer.channel) == 5, "five names"
    assert front.window[0].r.bb.width == 260 mm and front.window[0].r.bb.height == 30 mm, "windows"
    assert spacer.channel[0].r.bb.height - s[0].bar.bb.height == 0.6 mm, "0.3 mm play a side"
    # the slats are moved on the sheet: relate their own members only
    assert s[0].bar.bb.width == 134 mm + 150 mm + 10 mm, "slats stick out 10 mm"
    assert s[0].name.t.position.x - s[0].bar.bb.left == 134 mm - 125 mm + 8 mm, "names 8 mm in"
    assert s[3].name.t.bb.right - s[3].bar.bb.left <= 134 mm + 135 mm - 5 mm, "the longest name fits"
    assert front.header.t.bb.height <= 60 mm - 10 mm, "header fits its window"
    assert spacer_t - 3 mm >= 1 mm, "slats slide: 1 mm play in thickness"
}
