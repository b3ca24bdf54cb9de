# Request: a signature guide card for my grandmother, who has low vision, to keep in her purse:
# bank-card size 85.6 x 54 mm with 3.2 mm corner radius, cut from 1.5 mm black acrylic.
# - a signing window 70 x 12 mm (1 mm corner radius), centred left-right, its bottom edge
#   10 mm above the card's bottom edge;
# - "SIGN HERE" engraved 4 mm tall, centred over the signing window, baseline 3 mm above it;
# - a date window 25 x 8 mm (1 mm corner radius), its right edge in line with the signing
#   window's, its top 10 mm below the card's top edge; "DATE" engraved 3.5 mm tall to its left,
#   ending 3 mm before it, level with its middle;
# - a thumb notch to lift the card: a half circle 16 mm across, centred on the top edge;
# - a 4 mm key-ring hole, its centre 6 mm from the top and left edges.

units mm
thickness 1.5 mm

solid card {
    body = RoundedRectangle(center=(0, 0), width=85.6, height=54, corner_radius=3.2)

    hole sign_win {
        r = RoundedRectangle(center=(0, -10), width=70, height=12, corner_radius=1)
    }
    hole date_win {
        r = RoundedRectangle(center=(20, 10), width=25, height=8, corner_radius=1)
    }
    hole notch {
        c = Circle(center=(0, 27), diameter=16)
    }
    hole ring {
        c = Circle(center=(-36, 21), diameter=4)
    }
    drawing sign_label {
        t = Text("SIGN HERE", position=(0, 0), size=4)
    }
    drawing date_label {
        t = Text("DATE", position=(0, 10), size=3.5, anchor="end", valign="middle")
    }

    AlignCenterX(sign_win, body)
    sign_win.r.bb.bottom == body.bb.bottom + 10 mm
    AlignRight(date_win, sign_win)
    date_win.r.bb.top == body.bb.top - 10 mm
    Coincident(notch.c.center, body.top.midpoint)
    At(ring.c.center, body.top_left, dx=6, dy=-6)
    At(sign_label.t.position, sign_win.r.top.midpoint, dy=3)
    At(date_label.t.position, date_win.r.left.midpoint, dx=-3)

    assert body.bb.width == 85.6 mm and body.bb.height == 54 mm, "bank-card size"
    assert sign_win.r.bb.width == 70 mm and sign_win.r.bb.height == 12 mm, "signing window 70 x 12"
    assert sign_win.r.bb.bottom - body.bb.bottom == 10 mm, "window 10 mm above the bottom edge"
    assert date_win.r.bb.width == 25 mm and date_win.r.bb.height == 8 mm, "date window 25 x 8"
    assert body.bb.top - date_win.r.bb.top == 10 mm, "date window 10 mm below the top"
    assert ring.c.center.x - body.bb.left == 6 mm and body.bb.top - ring.c.center.y == 6 mm, "ring hole 6 mm in"
    assert distance(date_win, notch) >= 2 mm, "date window clear of the thumb notch"
    assert distance(date_label, notch) >= 2 mm, "DATE clear of the thumb notch"
    assert distance(sign_label, date_win) >= 2 mm, "SIGN HERE clear of the date window"
}
