# Request: a specimen tray for my daughter's rock and mineral collection, in 3 mm ply: an
# open finger-jointed tray 204 x 156 x 30 mm outside with 3 x 4 equal compartments (about
# 47 x 48 mm), the dividers halved into each other. Each compartment has its mineral's name
# engraved on the floor, 3.5 mm letters, 5 mm above the compartment's front edge, so the
# specimen sits above its label: front row QUARTZ FELDSPAR MICA CALCITE, middle row GYPSUM
# FLUORITE PYRITE GALENA, back row HEMATITE MAGNETITE TALC MALACHITE. "ROCKS & MINERALS"
# engraved filled on the front wall, 10 mm bold letters.

import "std/boxes.aidl"

units mm
thickness 3 mm

t = 3 mm
rows = 3
cols = 4
names = ["QUARTZ", "FELDSPAR", "MICA", "CALCITE",
         "GYPSUM", "FLUORITE", "PYRITE", "GALENA",
         "HEMATITE", "MAGNETITE", "TALC", "MALACHITE"]
inner_l = 204 mm - 2 * t
inner_w = 156 mm - 2 * t
cell_l = (inner_l - (cols - 1) * t) / cols
cell_w = (inner_w - (rows - 1) * t) / rows

assembly specimen_tray {
    tray = divider_tray(length=204 mm, width=156 mm, height=30 mm, rows=rows, cols=cols,
                        thickness=t, finger=12 mm)

    # the floor's names, drawn about the floor's centre (row 0 at the front, -y)
    drawing labels {
        floor = Rectangle(center=(0, 0), width=inner_l, height=inner_w, construction=true)
        for i in range(rows) {
            for j in range(cols) {
                n = Text(names[i * cols + j],
                         position=(-inner_l / 2 + cell_l / 2 + j * (cell_l + t),
                                   -inner_w / 2 + i * (cell_w + t) + 5 mm),
                         size=3.5, max_width=cell_l - 6 mm)
            }
        }
    }
    CenterInside(labels.floor, tray.body.bottom)
    CutInto(labels, tray.body.bottom)

    drawing title {
        words = Text("ROCKS & MINERALS", position=(0, 0), size=10, font="sans:Bold",
                     valign="middle", fill=true)
    }
    CenterInside(title, tray.body.front)
    CutInto(title, tray.body.front)

    # the request's numbers
    assert tray.length == 204 mm and tray.width == 156 mm and tray.height == 30 mm, "tray size"
    assert rows * cols == 12 and len(names) == 12, "12 compartments, 12 names"
    assert cell_l >= 47 mm and cell_l < 48 mm and cell_w >= 47 mm and cell_w <= 48 mm,
        "compartments about 47 x 48"
    assert labels.n[0][0].position.y - labels.floor.bb.bottom == 5 mm, "5 mm above the front edge"
    assert labels.n[2][3].position.y - labels.floor.bb.bottom == 2 * (cell_w + t) + 5 mm,
        "back row 5 mm above its compartments' front edge"
    assert labels.n[0][0].size == 3.5 mm, "3.5 mm letters"
}
