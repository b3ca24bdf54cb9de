# Request (office): an A4 clipboard from 4 mm birch plywood, 230 x 320 mm with 10 mm corner radii.
# At the top, centred: two 4.2 mm rivet holes 95 mm apart, 22 mm below the top edge, for a
# 100 mm lever clip, and an 8 mm hanging hole 7 mm below the top edge (its centre). Along the
# bottom edge an engraved 200 mm ruler whose zero is 15 mm from the left edge: a tick every mm
# running up from the edge, 2 mm long, 3.5 mm at every 5 mm, 5 mm at every 10 mm, with the
# centimetre numbers 0..20 (3 mm tall) above the long ticks, and "cm" after the 20. Above the
# ruler, centred, "PROPERTY OF J. MARSH" engraved in 5 mm single-stroke letters, baseline 20 mm
# above the bottom edge.

thickness 4 mm

param width = 230 mm, min = 200 mm, max = 260 mm
param height = 320 mm, min = 280 mm, max = 360 mm
param clip_pitch = 95 mm, min = 60 mm, max = 150 mm

zero_in = 15 mm
def tick(i) = 5 mm if i % 10 == 0 else (3.5 mm if i % 5 == 0 else 2 mm)

solid board {
    body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=10)
    hole rivets {
        a = Circle(center=(-clip_pitch / 2, height / 2 - 22), diameter=4.2)
        b = Circle(center=(clip_pitch / 2, height / 2 - 22), diameter=4.2)
    }
    hole hang {
        c = Circle(center=(0, height / 2 - 7), diameter=8)
    }
    drawing ruler {
        for i in range(201) {
            t = Line((-width / 2 + zero_in + i, -height / 2),
                     (-width / 2 + zero_in + i, -height / 2 + tick(i)))
        }
        for k in range(21) {
            n = Text(str(k), (-width / 2 + zero_in + 10 * k, -height / 2 + 6.5), size=3)
        }
        # FIX after the first valid program: W0513, "cm" 0.64 mm from the "20" read as "20cm"
        unit = Text("cm", (-width / 2 + zero_in + 200 + 5, -height / 2 + 6.5), size=3, anchor="start")
    }
    drawing owner {
        name = Text("PROPERTY OF J. MARSH", (0, -height / 2 + 20), size=5)
    }
    Fixed(body)

    assert abs(body.width - 230 mm) < 0.01 mm and abs(body.height - 320 mm) < 0.01 mm, "230 x 320"
    assert abs(rivets.b.center.x - rivets.a.center.x - 95 mm) < 0.01 mm, "rivets 95 apart"
    assert abs(body.bb.top - rivets.a.center.y - 22 mm) < 0.01 mm, "rivets 22 below the top"
    assert abs(rivets.a.center.x + rivets.b.center.x - 2 * body.center.x) < 0.01 mm, "rivets centred"
    assert abs(body.bb.top - hang.c.center.y - 7 mm) < 0.01 mm, "hanging hole 7 below the top"
    assert len(ruler.t) == 201, "0..200 mm, a tick every mm"
    assert abs(ruler.t[0].start.x - body.bb.left - 15 mm) < 0.01 mm, "zero 15 mm from the left edge"
    assert abs(ruler.t[200].start.x - ruler.t[0].start.x - 200 mm) < 0.01 mm, "200 mm ruler"
    assert abs(ruler.t[10].length - 5 mm) < 0.01 mm and abs(ruler.t[5].length - 3.5 mm) < 0.01 mm and abs(ruler.t[3].length - 2 mm) < 0.01 mm, "tick lengths"
    assert len(ruler.n) == 21, "numbers 0..20"
    assert abs(owner.name.position.y - body.bb.bottom - 20 mm) < 0.01 mm, "owner 20 above the edge"
}
