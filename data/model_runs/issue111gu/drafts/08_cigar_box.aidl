# Request: a cigar box for my father-in-law's 70th birthday, from 6 mm cedar ply: outside
# 250 x 170 x 70 mm, finger-jointed with 15 mm fingers, a lid that slides in over a low
# front (with its finger pull). On the lid: a 35 mm hole for a round press-in hygrometer
# (its 37 mm bezel sits on the lid), its centre 40 mm from the lid's right edge and halfway
# front to back; a 2 mm engraved band 12 mm in from the lid's edges all round; his
# monogram "R.H." 30 mm high in bold serif, and under it "70 YEARS - 1955 - 2025" 7 mm
# high, both engraved filled and centred between the lid's left edge and the hygrometer
# hole, the monogram's middle 8 mm above the lid's middle.

units mm
t = 6 mm
thickness t
import "std/boxes.aidl"

assembly cigar_box {
    b = sliding_lid_box(length=250 mm, width=170 mm, height=70 mm, thickness=t, finger=15 mm)

    hole hygro {
        c = Circle(center=(0, 0), diameter=35 mm)
    }
    hygro.c.center.x == b.lid.bb.right - 40 mm
    hygro.c.center.y == b.lid.bb.center_y
    CutInto(hygro, b.lid)

    drawing frame {
        r = Rectangle(corner=(0, 0), opposite=(200, 120), construction=true)
        band = Shell(r, -2 mm, join="miter", fill=true)
    }
    At(frame.r.bottom_left, b.lid.bb.bottom_left, dx=12 mm, dy=12 mm)
    At(frame.r.top_right, b.lid.bb.top_right, dx=-12 mm, dy=-12 mm)
    CutInto(frame, b.lid)

    drawing mark {
        mono = Text("R.H.", position=(0, 0), size=30 mm, font="serif:Bold", valign="middle",
                    fill=true)
        years = Text("70 YEARS - 1955 - 2025", position=(0, -30 mm), size=7 mm,
                     font="serif", valign="middle", fill=true)
    }
    mark.bb.center_x == (b.lid.bb.left + hygro.c.bb.left) / 2
    mark.mono.position.y == b.lid.bb.center_y + 8 mm
    CutInto(mark, b.lid)

    assert hygro.c.diameter == 35 mm, "35 mm hygrometer hole"
    assert b.lid.bb.right - hygro.c.center.x == 40 mm, "40 mm from the lid's right edge"
    assert frame.r.bb.left - b.lid.bb.left == 12 mm and b.lid.bb.top - frame.r.bb.top == 12 mm,
        "band 12 mm in"
    assert distance(mark, hygro) >= 5 mm, "lettering clear of the hygrometer bezel"
    assert distance(mark, frame) >= 3 mm, "lettering inside the band"
    assert distance(hygro, frame) >= 3 mm, "hygrometer hole inside the band"
    assert distance(mark, b.lid.pull) >= 3 mm and distance(frame, b.lid.pull) >= 2 mm,
        "engraving clear of the finger pull"
    assert mark.mono.size == 30 mm and mark.years.size == 7 mm, "letter sizes"
}
