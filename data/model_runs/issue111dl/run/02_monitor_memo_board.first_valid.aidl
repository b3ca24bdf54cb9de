# Request (office): a memo board that sticks out from the side of my monitor, 3 mm clear
# acrylic. A 110 x 220 panel with 10 mm round corners; on its left a 30 x 80 mounting tab
# (its top 20 mm below the panel's top) that I tape to the back of the monitor; the inside
# corners where the tab meets the panel rounded 4 mm. Engraved: "TO DO" in bold letters
# 10 high at the top, a 76 x 76 square marking where a 3" sticky note goes (its top 30 mm
# below the panel's top, centred), and under it a checklist of 5 rows 18 mm apart, each a
# 6 mm box and a writing line 74 mm long.

thickness 3 mm

param rows = 5, min = 2, max = 6

W = 110 mm
H = 220 mm
pitch = 18 mm

solid board {
    panel = RoundedRectangle(bottom_left=(0, 0), width=W, height=H, corner_radius=10)
    tab = RoundedRectangle(bottom_left=(-30, H - 20 - 80), width=34, height=80,
                           corner_radii=[6, 0, 0, 6])
    Fillet([[tab.top, panel.left], [tab.bottom, panel.left]], 4)

    drawing header {
        title = Text("TO DO", position=(W / 2, H - 18), size=10, font="sans:Bold", fill=true)
    }
    drawing note {
        square = Rectangle(center=(W / 2, H - 30 - 38), width=76, height=76)
    }
    drawing checklist {
        for i in range(rows) {
            box = Rectangle(center=(14, H - 124 - i * pitch + 3), width=6, height=6)
            rule = Line((22, H - 124 - i * pitch), (22 + 74, H - 124 - i * pitch))
        }
    }
    Fixed(panel)

    assert panel.bb.width == 110 mm and panel.bb.height == 220 mm, "panel 110 x 220"
    assert panel.bb.left - tab.bb.left == 30 mm, "tab stands 30 out"
    assert tab.bb.height == 80 mm, "tab 80 tall"
    assert panel.bb.top - tab.bb.top == 20 mm, "tab 20 below the top"
    assert note.square.bb.width == 76 mm, "3 inch note"
    assert panel.bb.top - note.square.bb.top == 30 mm, "note 30 below the top"
    assert len(checklist.box) == 5, "5 rows"
    assert checklist.rule[0].start.y - checklist.rule[1].start.y == 18 mm, "rows 18 apart"
    assert checklist.rule[0].length == 74 mm, "lines 74 long"
}
