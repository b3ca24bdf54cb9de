# A laser-cut lid for a small board, made from the board's own drawing: the outline and the
# mounting holes come from KiCad's Edge.Cuts layer (examples/parts/pcb_board.dxf, written by
# docs/dev/make_drawings.py).  The lid is the board outline grown by a 3 mm margin,
# with standoff holes on the board's holes and a USB cut-out placed from the board's edge.
units mm

param margin = 3 mm
param standoff_d = 3.4 mm    # M3 clearance through the lid
param usb_width = 9.5 mm     # a USB-C receptacle's opening
param usb_from_left = 16 mm  # its centre from the board's left edge

solid lid {
    board = Drawing2D("parts/pcb_board.dxf", layer="Edge.Cuts", construction=true)
    Fixed(board.origin)
    body = Offset(board.outlines[0], margin)

    for c in board.circles {
        hole standoff {
            h = Circle(center=(0, 0), diameter=standoff_d)
        }
        Concentric(standoff.h, c)
    }

    hole usb {
        r = RoundedRectangle(center=(0, 0), width=usb_width, height=6, corner_radius=1)
    }
    usb.r.center.x == board.bb.left + usb_from_left
    usb.r.bb.bottom == board.bb.top - 2  # 2 mm over the board's edge
}
