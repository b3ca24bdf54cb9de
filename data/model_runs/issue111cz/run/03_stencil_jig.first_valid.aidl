# Request (electronics): a solder-paste stencil printing jig for a 50 x 30 x 1.6 mm PCB, four
# acrylic parts. All plates 160 x 120 mm, registered by two 4 mm steel dowel pins 136 mm apart
# on the long centre line.
# - base, 3 mm: pin holes 3.9 mm (press fit); "STENCIL JIG 50x30" engraved 8 mm tall, 12 mm
#   above the bottom edge.
# - nest, 1.6 mm (as thick as the board): a pocket 50.2 x 30.2 in the middle for the board, with
#   a 14 mm round finger notch centred on the pocket's right end to lift the board out; pin holes
#   4.2 mm; engraved "PCB" 5 mm tall 6 mm above the pocket.
# - stencil frame, 3 mm: a 100 x 70 window (3 mm corner radii) over the board, where the stencil
#   foil is taped on; left pin hole 4.2 mm round, right one a 4.2 x 8 mm slot along the pins'
#   line (so the frame never binds); an engraved arrow-free "TOP" 6 mm tall, 10 mm below its top edge.
# - squeegee, 3 mm: 80 x 45 mm, top corners rounded 8 mm, the wiping (bottom) edge straight with
#   sharp corners, a 40 x 12 mm finger slot 12 mm above the wiping edge.

thickness 3 mm

PW = 50 mm      # board
PH = 30 mm
FIT = 0.2 mm
PLATE_W = 160 mm
PLATE_H = 120 mm
PIN_X = 68 mm   # pins at +-68: 136 apart

def plate_body() -> solid {
    body = Rectangle(center=(0, 0), width=PLATE_W, height=PLATE_H)
}

assembly stencil_jig {
    solid base {
        body = Rectangle(center=(0, 0), width=PLATE_W, height=PLATE_H)
        hole pin_l { c = Circle(center=(-PIN_X, 0), diameter=3.9 mm) }
        hole pin_r { c = Circle(center=(PIN_X, 0), diameter=3.9 mm) }
        drawing title {
            t = Text("STENCIL JIG 50x30", position=(0, -PLATE_H / 2 + 12 mm), size=8 mm)
        }
    }

    solid nest {
        thickness 1.6 mm
        body = Rectangle(center=(0, 0), width=PLATE_W, height=PLATE_H)
        hole pocket {
            board = Rectangle(center=(0, 0), width=PW + FIT, height=PH + FIT)
            notch = Circle(center=((PW + FIT) / 2, 0), diameter=14 mm)
        }
        hole pin_l { c = Circle(center=(-PIN_X, 0), diameter=4.2 mm) }
        hole pin_r { c = Circle(center=(PIN_X, 0), diameter=4.2 mm) }
        drawing label {
            t = Text("PCB", position=(0, (PH + FIT) / 2 + 6 mm), size=5 mm)
        }
    }

    solid frame {
        body = Rectangle(center=(0, 0), width=PLATE_W, height=PLATE_H)
        hole window {
            w = RoundedRectangle(center=(0, 0), width=100 mm, height=70 mm, corner_radius=3 mm)
        }
        hole pin_l { c = Circle(center=(-PIN_X, 0), diameter=4.2 mm) }
        hole pin_r { s = Slot(center=(PIN_X, 0), length=8 mm, width=4.2 mm) }
        drawing label {
            t = Text("TOP", position=(0, PLATE_H / 2 - 10 mm), size=6 mm, valign="top")
        }
    }

    solid squeegee {
        blade = RoundedRectangle(center=(0, 0), width=80 mm, height=45 mm,
                                 corner_radii=[8 mm, 8 mm, 0 mm, 0 mm])
        hole grip {
            s = Slot(center=(0, -45 mm / 2 + 12 mm + 6 mm), length=40 mm, width=12 mm)
        }
    }

    # on the sheet: side by side
    RightOf(nest, base, gap=5 mm)
    Above(frame, base, gap=5 mm)
    RightOf(squeegee, frame, gap=5 mm)
    AlignBottom(squeegee, frame)

    # in 3D: stacked on the pins; the squeegee lies beside the jig
    Place(base, position=(0, 0, 0), face="up")
    Place(nest, position=(0, 0, 3 mm), face="up")
    Place(frame, position=(0, 0, 4.6 mm), face="up")
    Place(squeegee, position=(0, -100 mm, 0), face="up")

    assert nest.pocket.board.bb.width == 50.2 mm and nest.pocket.board.bb.height == 30.2 mm,
        "pocket 50.2 x 30.2"
    assert base.pin_r.c.center.x - base.pin_l.c.center.x == 136 mm, "pins 136 apart"
    assert nest.pin_r.c.center.x - nest.pin_l.c.center.x == 136 mm, "nest pins 136 apart"
    assert frame.pin_r.s.center.x - frame.pin_l.c.center.x == 136 mm, "frame pins 136 apart"
    assert frame.window.w.bb.width == 100 mm and frame.window.w.bb.height == 70 mm, "window"
    assert nest.pocket.notch.center.x - nest.pocket.board.bb.center_x == 25.1 mm, "notch on the end"
    assert squeegee.grip.s.bb.bottom - squeegee.blade.bb.bottom == 12 mm, "slot 12 above the edge"
    assert base.title.t.position.y - base.body.bb.bottom == 12 mm, "title 12 up"
}
