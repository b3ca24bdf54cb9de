# Request (electronics): a PCB holder for soldering, all 3 mm birch ply, for boards 10 to 70 mm wide.
# - Base 180 x 110 mm, corners r5. Two 4.5 mm slots (M4 bolts with wing nuts) along y, 100 mm apart,
#   60 mm travel (centre to centre) for the sliding jaw; two 4.5 mm holes for the fixed jaw, also
#   100 mm apart, 40 mm behind the base's centre.
# - Each jaw is two layers: a bottom layer 130 x 24 mm and a top layer 130 x 20 mm flush with the
#   bottom layer's outer edge, so each jaw shows a 4 mm ledge toward the other jaw; the board rests
#   on the two ledges between the top layers' faces. Bolt holes 12 mm from the bottom layer's edges.
# - A board-width scale engraved on the base right of the sliding jaw: a tick every 5 mm
#   (10 mm ticks longer, labelled 10 ... 70), read at the sliding jaw's back edge.
# - "PCB HOLDER" engraved on the fixed jaw's top layer.
# Shown holding a 50 mm board.

thickness 3 mm

param board = 50 mm, min = 10 mm, max = 70 mm   # board width between the jaws' top layers

T = 3 mm
M4 = 4.5 mm
FIXED_Y = 40 mm          # fixed jaw's bolt line
SPAN = 100 mm            # bolt spacing
LEDGE = 4 mm

# the sliding jaw's bolt line for a board width w: the fixed top layer's front face is at
# FIXED_Y - 12 + LEDGE, the sliding top layer's back face at h + 12 - LEDGE
def slide_y(w) = FIXED_Y - 12 mm + LEDGE - w - (12 mm - LEDGE)

SLOT_TOP = slide_y(10 mm)
SLOT_BOT = slide_y(70 mm)

# one jaw layer: width 24 (bottom) or 20 (top), ledge toward -y (fixed jaw) or +y (sliding jaw)
def layer(y0=0 mm, w=24 mm, ledge_side=-1) -> solid {
    body = Rectangle(center=(0, y0 - ledge_side * (24 mm - w) / 2), width=130, height=w)
    hole bolts {
        a = Circle(center=(-SPAN / 2, y0), diameter=M4)
        b = Circle(center=(SPAN / 2, y0), diameter=M4)
    }
}

assembly pcb_holder {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=180, height=110, corner_radius=5)
        hole fixed_holes {
            a = Circle(center=(-SPAN / 2, FIXED_Y), diameter=M4)
            b = Circle(center=(SPAN / 2, FIXED_Y), diameter=M4)
        }
        hole slots {
            a = Slot(start=(-SPAN / 2, SLOT_BOT), end=(-SPAN / 2, SLOT_TOP), width=M4)
            b = Slot(start=(SPAN / 2, SLOT_BOT), end=(SPAN / 2, SLOT_TOP), width=M4)
        }
        drawing scale {
            for w in range(10, 71, 5) {
                tick = Line(start=(68, slide_y(w * 1 mm) + 12 mm),
                            end=(68 + (8 if w % 10 == 0 else 4), slide_y(w * 1 mm) + 12 mm))
            }
            for w in range(10, 71, 10) {
                num = Text(str(w), position=(82, slide_y(w * 1 mm) + 12 mm), size=3.5,
                           anchor="start", valign="middle")
            }
        }
        assert slots.b.start.x - slots.a.start.x == 100 mm, "slots 100 mm apart"
        assert slots.a.end.y - slots.a.start.y == 60 mm, "60 mm travel"
        assert fixed_holes.a.center.y - body.center.y == 40 mm, "fixed jaw 40 mm behind the centre"
        assert scale.bb.right <= body.bb.right - 3 mm, "scale on the base"
    }

    fixed_bottom = layer(y0=FIXED_Y, w=24 mm, ledge_side=-1)
    fixed_top = layer(y0=FIXED_Y, w=20 mm, ledge_side=-1)
    slide_bottom = layer(y0=slide_y(board), w=24 mm, ledge_side=1)
    slide_top = layer(y0=slide_y(board), w=20 mm, ledge_side=1)

    drawing label {
        t = Text("PCB HOLDER", position=(0, FIXED_Y + 2), size=5, valign="middle")
    }
    CutInto(label, fixed_top)

    # the request's numbers
    assert fixed_bottom.body.bb.top == fixed_top.body.bb.top, "fixed layers flush at the back"
    assert fixed_top.body.bb.bottom - fixed_bottom.body.bb.bottom == 4 mm, "4 mm ledge (fixed)"
    assert slide_bottom.body.bb.top - slide_top.body.bb.top == 4 mm, "4 mm ledge (sliding)"
    assert fixed_top.body.bb.bottom - slide_top.body.bb.top == board, "board between top layers"
    assert fixed_bottom.bolts.a.center.y - fixed_bottom.body.bb.bottom == 12 mm, "bolts 12 mm in"
    assert slide_y(70 mm) >= base.slots.a.start.y - 0.001 mm, "70 mm board within travel"
    assert slide_y(10 mm) <= base.slots.a.end.y + 0.001 mm, "10 mm board within travel"
    assert label.bb.width <= 120 mm, "label on the jaw"

    # 3D: layers stacked on the base where they are drawn
    Place(base, position=(0, 0, 0))
    Place(fixed_bottom, position=(0, 0, T))
    Place(slide_bottom, position=(0, 0, T))
    Place(fixed_top, position=(0, 0, 2 * T))
    Place(slide_top, position=(0, 0, 2 * T))

    # flat on the sheet: the four layers in a column right of the base
    RightOf(fixed_bottom, base, gap=5)
    Below(fixed_top, fixed_bottom, gap=5)
    Below(slide_bottom, fixed_top, gap=5)
    Below(slide_top, slide_bottom, gap=5)
    AlignTop(fixed_bottom, base)
    AlignLeft(fixed_top, fixed_bottom)
    AlignLeft(slide_bottom, fixed_bottom)
    AlignLeft(slide_top, fixed_bottom)
}
