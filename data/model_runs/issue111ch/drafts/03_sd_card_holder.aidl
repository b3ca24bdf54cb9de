# Request (electronics): a bench holder for the memory cards of my cameras, Raspberry Pis and
# 3D printer, glued up from three layers of 3 mm ply, 130 x 78 mm with 6 mm corners. The top
# two layers are slotted right through, the bottom one is plain, so each slot is a 6 mm deep
# pocket. On the left, 12 full-size SD cards stand in two columns of six: slots 24.5 x 2.6 mm,
# columns 30 mm apart, rows 8 mm apart. On the right, 18 microSD cards in three columns of
# six: slots 11.5 x 1.4 mm, columns 16 mm apart, rows 8 mm apart. "SD" and "microSD"
# engraved above their columns, 5 mm letters.

units mm
thickness 3 mm

param rows = 6, min = 3, max = 7
param pitch = 8 mm, min = 7 mm, max = 10 mm

def layer(slots=true, labels=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=130, height=78, corner_radius=6)
    if slots {
        hole sd {
            r = Rectangle(center=(-45, -26), width=24.5, height=2.6)
        }
        sd_grid = GridPattern(sd, rows, 2, col_spacing=30, row_spacing=pitch)
        hole micro {
            r = Rectangle(center=(18, -26), width=11.5, height=1.4)
        }
        micro_grid = GridPattern(micro, rows, 3, col_spacing=16, row_spacing=pitch)
    }
    if labels {
        drawing words {
            sd_t = Text("SD", (-30, 26), size=5, valign="middle")
            micro_t = Text("microSD", (34, 26), size=5, valign="middle")
        }
    }
}

assembly holder {
    base = layer(slots=false)
    middle = layer()
    top = layer(labels=true)

    # flat on the sheet
    RightOf(middle, base, gap=8)
    RightOf(top, middle, gap=8)
    AlignBottom(middle, base)
    AlignBottom(top, base)

    # glued up
    Place(base, position=(0, 0, 0))
    Place(middle, position=(0, 0, 3))
    Place(top, position=(0, 0, 6))

    assert len(top.sd_grid) == 12, "12 SD cards"
    assert len(top.micro_grid) == 18, "18 microSD cards"
    assert top.sd_grid[0].r.width == 24.5 mm and top.sd_grid[0].r.height == 2.6 mm, "SD slot 24.5 x 2.6"
    assert top.micro_grid[0].r.width == 11.5 mm and top.micro_grid[0].r.height == 1.4 mm, "microSD slot 11.5 x 1.4"
    assert top.sd_grid[1].r.center.x - top.sd_grid[0].r.center.x == 30 mm, "SD columns 30 apart"
    assert top.micro_grid[1].r.center.x - top.micro_grid[0].r.center.x == 16 mm, "microSD columns 16 apart"
    assert top.sd_grid[2].r.center.y - top.sd_grid[0].r.center.y == 8 mm, "rows 8 apart"
    assert top.body.bb.width == 130 mm and top.body.bb.height == 78 mm, "130 x 78"
    # every slot inside the plate, 4 mm clear of its edge
    assert top.sd_grid[11].r.bb.top <= top.body.bb.top - 4 mm, "top row clear of the edge"
    assert top.micro_grid[17].r.bb.right <= top.body.bb.right - 4 mm, "right column clear of the edge"
}
