# Request: a stick-incense holder for the hallway shelf, cut from 4 mm birch ply.
# An ash tray of two glued layers, both a 240 x 70 mm stadium (fully round ends): a solid
# base, and on it a rim layer whose opening is inset 6 mm, so the ash stays in.
# An upright fin 50 mm wide stands across the tray, its middle 30 mm from the tray's left
# end, 45 mm tall above the base with R10 top corners, glued by two 12 mm tabs into
# mortises through the base. In the fin a vertical 2.4 x 5 mm slot, its middle 35 mm above
# the base, holds a stick so it leans up at about 30 deg over the tray; a standard 230 mm
# stick at 30 deg must not reach past the tray's opening. "BREATHE" engraved on the fin's
# face toward the tray.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
tray_w = 240 mm
tray_h = 70 mm
rim = 6 mm
fin_x = -tray_w / 2 + 30 mm      # the fin's middle, in the base's frame
fin_w = 50 mm
fin_h = 45 mm

assembly incense_holder {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_h, corner_radius=tray_h / 2)
        m = tab_and_slot(part="slot", length=fin_w, thickness=t, tabs=2, tab=12 mm, screw=0,
                         rotation=90 deg, cx=fin_x, cy=0 mm)
    }

    solid rim_layer {
        body = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_h, corner_radius=tray_h / 2)
        hole opening {
            o = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_h, corner_radius=tray_h / 2)
            w = Inset(o, rim)
            Fixed(o)
        }
    }

    solid fin {
        # y = 0 is the base's top face; the tabs reach down through the base to y = -t
        body = RoundedRectangle(center=(0, (fin_h - t) / 2), width=fin_w, height=fin_h + t,
                                corner_radii=[10 mm, 10 mm, 0, 0])
        tabs = tab_and_slot(part="tab", length=fin_w, thickness=t, tabs=2, tab=12 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-t)
        hole stick {
            s = Slot(center=(0, 35 mm), length=5 mm, width=2.4 mm, rotation=90 deg)
        }
        drawing word {
            w = Text("BREATHE", position=(0, 18 mm), size=5 mm, valign="middle")
        }
    }

    # flat on the sheet: the rim layer under the base, the fin to the right
    Below(rim_layer, base, gap=5 mm)
    AlignLeft(rim_layer, base)
    RightOf(fin, base, gap=5 mm)
    AlignTop(fin, base)

    # assembled: base on the shelf, rim layer glued on it, fin standing in the mortises,
    # its engraved face toward the tray (+x)
    Place(base, position=(0, 0, 0))
    Place(rim_layer, position=(0, 0, t))
    Place(fin, position=(fin_x - t / 2, 0, t), face="right", up="up")

    # the request's numbers
    assert base.body.bb.width == 240 mm and base.body.bb.height == 70 mm, "tray 240 x 70"
    assert rim_layer.opening.bb.width == 240 mm - 2 * 6 mm, "rim 6 mm wide"
    assert base.m.slot[0].bb.center_x - base.body.bb.left == 30 mm, "fin 30 mm from the left end"
    assert fin.body.bb.height - t == 45 mm, "fin 45 mm above the base"
    assert fin.stick.bb.center_y - fin.body.bb.bottom - t == 35 mm, "stick slot 35 mm up"
    assert rim_layer.opening.bb.right - base.m.slot[0].bb.center_x >= 230 mm * cos(30 deg),
        "a 230 mm stick at 30 deg stays over the tray"
}
