# Request (parties: poker night): a chip tray for five rows of fifty 40 mm clay chips
# (41 mm with slack, 3.3 mm thick), glued up from four layers of 6 mm walnut ply: a solid
# base under three identical layers, each cut with five rows 39 mm wide and 175 mm long at
# 45 mm pitch, so each chip stands on edge resting on the top layer's edges and hangs down
# into the rows without touching the base. The tray is 250 x 205 mm with R10 corners. The
# top layer is engraved filled with the chip values 1, 5, 25, 100, 500 in the front margin,
# one under each row, and FRIDAY NIGHT POKER across the back margin. A fifth piece: a 50 mm
# dealer button with a filled DEALER and an engraved ring 4 mm in from its edge.

thickness 6 mm
t = 6 mm

tray_w = 250 mm
tray_d = 205 mm
row_w = 39 mm
row_len = 175 mm
pitch = 45 mm
chip_d = 41 mm
values = ["1", "5", "25", "100", "500"]

def layer(top=false) -> solid {
    plate = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_d, corner_radius=10)
    hole row {
        r = Rectangle(center=(-2 * pitch, 0), width=row_w, height=row_len)
    }
    rows = LinearPattern(row, 5, (pitch, 0))
    if top {
        drawing words {
            for i in range(5) {
                v = Text(values[i], position=((i - 2) * pitch, -(row_len / 2 + tray_d / 2) / 2),
                         size=8, font="sans:Bold", valign="middle", fill=true)
            }
            title = Text("FRIDAY NIGHT POKER", position=(0, (row_len / 2 + tray_d / 2) / 2),
                         size=8, font="sans:Bold", valign="middle", fill=true)
        }
    }
}

assembly chip_tray {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_d, corner_radius=10)
    }
    low = layer()
    mid = layer()
    top = layer(top=true)

    solid button {
        disc = Circle(center=(0, 0), diameter=50)
        drawing face {
            ring = Circle(center=(0, 0), radius=21)
            word = Text("DEALER", position=(0, 0), size=7, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    # on the sheet
    RightOf(low, base, gap=8)
    AlignBottom(low, base)
    Above(mid, base, gap=8)
    AlignLeft(mid, base)
    RightOf(top, mid, gap=8)
    AlignBottom(top, mid)
    RightOf(button, low, gap=8)
    AlignBottom(button, low)

    # in 3D: the stack
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(low, position=(0, 0, t), face="up", up="back")
    Place(mid, position=(0, 0, 2 * t), face="up", up="back")
    Place(top, position=(0, 0, 3 * t), face="up", up="back")
    Place(button, position=(170, 0, 0), face="up", up="back")

    # the request's numbers
    assert len(top.rows) == 5
    assert top.row.r.width == 39 mm and top.row.r.height == 175 mm
    assert top.rows[1].r.center.x - top.rows[0].r.center.x == 45 mm
    assert base.plate.width == 250 mm and base.plate.height == 205 mm
    # a chip resting on the row's edges hangs this far below the top face: clear of the base
    assert chip_d / 2 - sqrt((chip_d / 2) ** 2 - (row_w / 2) ** 2) < 3 * t, "chips touch the base"
    assert 50 * 3.3 mm <= row_len, "fifty chips fit a row"
    assert button.disc.diameter == 50 mm and button.face.ring.radius == 25 mm - 4 mm
}
