# Request (workshop): a laser-cut try square for marking out, from 6 mm birch ply.
# The blade is 40 mm wide and reaches 260 mm past the stock's inner face; its first 30 mm
# sit inside the stock (blade 290 mm long overall). Along the blade's top edge an engraved
# mm scale from 0 (the stock's inner face) to 250 mm: 3 mm ticks every mm, 5 mm ticks every
# 5 mm, 7 mm ticks every 10 mm with the cm number (0 to 25, 3 mm high) under it. A 6 mm
# hanging hole 10 mm from the blade's far end, 12 mm up from its bottom edge, and
# "TRY SQUARE" engraved along the blade under the scale.
# The stock is 150 mm long and 30 mm wide, three 6 mm layers glued: two full cheeks
# (30 x 150) and a 30 x 110 core under the blade, so the blade sits flush with the stock's
# top end. Four 5 mm dowel holes 15 mm in from the stock's outer edge, at 20, 80, 120 and 140
# mm up from the stock's bottom, through cheeks, core (20, 80) and blade (120, 140).
# Engrave "90" on the front cheek.

thickness 6 mm

blade_w = 40 mm
reach = 260 mm       # past the stock's inner face
stock_len = 150 mm
stock_w = 30 mm
core_len = 110 mm
dowel_d = 5 mm
dowel_ys = [20 mm, 80 mm, 120 mm, 140 mm]

# stock frame: the stock's inner face is x = 0, its bottom y = 0; it runs to x = -30

def dowels(ys=[20 mm]) -> hole {
    for k in range(len(ys)) {
        d = Circle(center=(-stock_w / 2, ys[k]), diameter=dowel_d)
    }
}

def cheek(mark=false) -> solid {
    body = Rectangle(bottom_left=(-stock_w, 0), width=stock_w, height=stock_len)
    holes = dowels(ys=dowel_ys)
    if mark {
        drawing label {
            t = Text("90", position=(-stock_w / 2, 50), size=8, valign="middle", rotation=90 deg)
        }
    }
}

assembly try_square {
    solid blade {
        body = Rectangle(bottom_left=(-stock_w, core_len), width=stock_w + reach, height=blade_w)
        holes = dowels(ys=[120 mm, 140 mm])
        hole hang { c = Circle(center=(reach - 10 mm, core_len + 12 mm), diameter=6 mm) }
        drawing scale {
            for i in range(251) {
                tick = Line((i * 1 mm, core_len + blade_w),
                            (i * 1 mm, core_len + blade_w - (7 mm if i % 10 == 0 else (5 mm if i % 5 == 0 else 3 mm))))
            }
            for j in range(26) {
                num = Text(str(j), position=(j * 10 mm, core_len + blade_w - 11 mm), size=3)
            }
            title = Text("TRY SQUARE", position=(120 mm, core_len + 10 mm), size=6, valign="middle")
        }
        assert len(scale.tick) == 251, "a tick every mm from 0 to 250"
        assert len(scale.num) == 26, "cm numbers 0 to 25"
    }
    solid core {
        body = Rectangle(bottom_left=(-stock_w, 0), width=stock_w, height=core_len)
        holes = dowels(ys=[20 mm, 80 mm])
    }
    back_cheek = cheek()
    front_cheek = cheek(mark=true)

    # on the sheet: laid out side by side for cutting
    Fixed(blade)
    Below(core, blade, gap=10)
    AlignLeft(core, blade)
    RightOf(back_cheek, core, gap=10)
    AlignBottom(back_cheek, core)
    RightOf(front_cheek, back_cheek, gap=10)
    AlignBottom(front_cheek, back_cheek)

    # glued up: back cheek, then core and blade in the middle layer, then the front cheek
    Place(back_cheek, position=(0, 0, 0))
    Place(core, position=(0, 0, 6 mm))
    Place(blade, position=(0, 0, 6 mm))
    Place(front_cheek, position=(0, 0, 12 mm))

    # the request's numbers
    assert blade.body.bb.right - 0 == 260 mm, "blade reaches 260 mm past the stock face"
    assert blade.body.width == 290 mm, "blade 290 long overall"
    assert blade.body.height == 40 mm, "blade 40 wide"
    assert back_cheek.body.height == 150 mm and back_cheek.body.width == 30 mm, "stock 150 x 30"
    assert core.body.height == 110 mm, "core 110 long"
    assert core.body.height + blade.body.height == back_cheek.body.height, "blade flush with the stock's top"
    assert blade.hang.c.center.x == 250 mm, "hanging hole 10 mm from the far end"
    assert len(back_cheek.holes.d) == 4, "four dowel holes"
}
